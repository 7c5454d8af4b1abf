// The `angioray` command line: parses options and dispatches to gui/commands.h. No work here.
#include <cstdio>
#include <exception>

#include <CLI/CLI.hpp>

#include "gui/commands.h"

namespace {

void addInfo(CLI::App& app, angio::InfoOptions& o) {
  auto* cmd = app.add_subcommand("info", "Print dimensions, spacing, orientation and HU statistics");
  cmd->add_option("VOLUME", o.volume, "Volume file or DICOM folder")->required();
  cmd->add_option("--labels", o.labels, "Label volume on the same grid (4-bit labels)");
  cmd->add_option("--tf", o.tf, "Also report the fraction of voxels this TF makes visible");
}

void addRender(CLI::App& app, angio::RenderOptions& o) {
  auto* cmd = app.add_subcommand("render", "Render a volume to an image file (.png, .tif, .exr)");
  cmd->add_option("VOLUME", o.volume, "Volume file or DICOM folder")->required();
  cmd->add_option("--out,-o", o.out, "Output image (.png 8-bit, .tif 16-bit, .exr float)")->required();
  cmd->add_option("--labels", o.labels, "Label volume on the same grid");
  cmd->add_option("--tf", o.tf, "TF preset id or name, or a TF JSON file")->capture_default_str();
  cmd->add_option("--axis", o.axis, "Rotation axis")->check(CLI::IsMember({"i", "j", "k"}))
      ->capture_default_str();
  cmd->add_option("--angle", o.angleDeg, "Rotation angle in degrees")->capture_default_str();
  cmd->add_option("--quality", o.quality, "Quality level (sampling defaults)")
      ->check(CLI::IsMember({"fast", "medium", "high"}))->capture_default_str();
  cmd->add_option("--isd", o.isd, "Image sampling distance (voxel units)")->check(CLI::PositiveNumber);
  cmd->add_option("--osd", o.osd, "Object sampling distance (voxel units)")->check(CLI::PositiveNumber);
  cmd->add_option("--filter", o.filter, "Reconstruction filter")
      ->check(CLI::IsMember({"nearest", "trilinear", "mean"}));
  cmd->add_option("--shading", o.shading, "Headlight diffuse shading")->check(CLI::IsMember({"on", "off"}));
  cmd->add_option("--ka", o.ka, "Ambient coefficient")->check(CLI::Range(0.0, 10.0));
  cmd->add_option("--kd", o.kd, "Diffuse coefficient")->check(CLI::Range(0.0, 10.0));
  cmd->add_option("--ert", o.ert, "Early ray termination opacity (1 = off)")->check(CLI::Range(0.0, 1.0));
  cmd->add_flag("--mip", o.mip, "Maximum intensity projection instead of DVR");
  cmd->add_option("--window", o.window, "MIP window width (HU)")->check(CLI::PositiveNumber);
  cmd->add_option("--level", o.level, "MIP window centre (HU)");
  cmd->add_flag("--reference", o.reference, "Use the plain reference raycaster (same image, slower)");
}

void addPhantom(CLI::App& app, angio::PhantomOptionsCli& o) {
  auto* cmd = app.add_subcommand("phantom", "Generate the peripheral run-off CTA phantom");
  cmd->add_option("OUT", o.out, "Output volume (.mha, .nrrd, .nii.gz)")->required();
  cmd->add_option("--size", o.size, "Voxels as IxJxK")->capture_default_str();
  cmd->add_option("--seed", o.seed, "Noise seed")->capture_default_str();
  cmd->add_option("--centerlines", o.centerlines, "Also write ground-truth centerlines (.csv)");
}

void addBench(CLI::App& app, angio::BenchOptionsCli& o) {
  auto* cmd = app.add_subcommand("bench", "Time the raycasters over many angles (median, min, max)");
  cmd->add_option("VOLUME", o.volume, "Volume (default: the generated phantom)");
  cmd->add_option("--size", o.size, "Phantom voxels as IxJxK when no VOLUME")->capture_default_str();
  cmd->add_option("--tf", o.tf, "TF preset or file")->capture_default_str();
  cmd->add_option("--axis", o.axis, "Rotation axis")->check(CLI::IsMember({"i", "j", "k"}))
      ->capture_default_str();
  cmd->add_option("--angles", o.angles, "Angles per level")->check(CLI::Range(1, 3600))
      ->capture_default_str();
  cmd->add_option("--threads", o.threads, "Worker threads (0 = all cores)")->check(CLI::Range(0, 1024));
  cmd->add_flag("--reference", o.reference, "Also time the reference raycaster (slow)");
  cmd->add_flag("!--no-contributions", o.contributions, "Skip the technique-off rows");
  cmd->add_option("--json", o.json, "Also write the results as JSON");
}

void addDemo(CLI::App& app, angio::DemoOptions& o) {
  auto* cmd = app.add_subcommand(
      "demo", "Generate the phantom and render it at the three quality levels (the default job)");
  cmd->add_option("--out-dir", o.outDir, "Where the PNGs go")->capture_default_str();
  cmd->add_option("--size", o.size, "Phantom voxels as IxJxK")->capture_default_str();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"angioray " ANGIORAY_VERSION " - CPU volume rendering for CT angiography"};
  app.set_version_flag("--version", ANGIORAY_VERSION);
  angio::InfoOptions info;
  angio::RenderOptions render;
  angio::PhantomOptionsCli phantom;
  angio::DemoOptions demo;
  angio::BenchOptionsCli bench;
  addInfo(app, info);
  addRender(app, render);
  addPhantom(app, phantom);
  addDemo(app, demo);
  addBench(app, bench);
  app.require_subcommand(0, 1);
  CLI11_PARSE(app, argc, argv);

  try {
    if (app.got_subcommand("info")) return angio::runInfo(info);
    if (app.got_subcommand("render")) return angio::runRender(render);
    if (app.got_subcommand("phantom")) return angio::runPhantom(phantom);
    if (app.got_subcommand("bench")) return angio::runBench(bench);
    // No subcommand: the main job. Until the GUI lands it is always the headless demo.
    return angio::runDemo(demo);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "angioray: error: %s\n", error.what());
    return 1;
  }
}
