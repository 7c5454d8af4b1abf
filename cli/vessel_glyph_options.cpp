#include "cli/vessel_glyph_options.h"

#include <filesystem>
#include <stdexcept>

#include <CLI/CLI.hpp>

#include "cli/number_checks.h"
#include "io/tf_file.h"
#include "render/region_tfs.h"
#include "vessel/vessel_glyph_spec.h"

namespace angio {

namespace {

void requireOption(bool given, bool needed, const char* option, const char* needs) {
  if (given && !needed) throw std::invalid_argument(std::string(option) + " needs " + needs);
}

}  // namespace

void addVesselGlyphOptions(CLI::App& cmd, VesselGlyphCliOptions& o) {
  cmd.add_option("--centerlines", o.centerlines,
                 "VesselGlyph focus+context rendering along these centerlines (.vtp, .mrk.json, .csv)");
  cmd.add_option("--vg-focus", o.focus,
                 "Focus shape: circle:radius=R, R in mm (3, 3mm) or a factor "
                 "of the vessel radius (2.0x) [circle:radius=2.0x]");
  cmd.add_option("--vg-context", o.context,
                 "Context shape: slab:front=MM,back=MM[,width=MM|inf], "
                 "tube:radius=R or none [slab:front=20,back=20,width=40]");
  cmd.add_option("--focus-tf", o.focusTf, "TF of the focus region (preset or file) [--tf]");
  cmd.add_option("--context-tf", o.contextTf,
                 "TF of the context region (preset or file) [--tf, faded to 20 % opacity]");
  cmd.add_option("--vg-outside", o.outside,
                 "Outside the regions: clip, or a TF to render it with [clip]");
  cmd.add_flag("--cleft", o.cleft, "Foreground cleft: remove the context in front of the focus");
  cmd.add_flag("--half-vessel", o.halfVessel, "Clip the focus at the centerline's depth");
  cmd.add_flag("--hybrid-cpr", o.hybrid, "DVR+CPR hybrid: the projected CPR in the focus footprint");
  cmd.add_option("--hybrid-path", o.hybridPath, "Hybrid: path index or all [all]");
  cmd.add_option("--transition", o.transitionMm, "Hybrid: smooth transition band in mm [0]")
      ->check(numberAtLeast(0));
  cmd.add_option("--cpr-window", o.cprWindow,
                 "Hybrid: grey CPR window width (HU) instead of the "
                 "focus TF's colors")
      ->check(numberAbove(0));
  cmd.add_option("--cpr-level", o.cprLevel, "Hybrid: grey CPR window centre (HU)");
}

std::optional<VesselGlyphRecipe> vesselGlyphRecipe(const VesselGlyphCliOptions& o,
                                                   const std::string& baseTf) {
  const bool vg = !o.centerlines.empty();
  const char* needs = "--centerlines";
  requireOption(o.focus.has_value(), vg, "--vg-focus", needs);
  requireOption(o.context.has_value(), vg, "--vg-context", needs);
  requireOption(o.focusTf.has_value(), vg, "--focus-tf", needs);
  requireOption(o.contextTf.has_value(), vg, "--context-tf", needs);
  requireOption(o.outside.has_value(), vg, "--vg-outside", needs);
  requireOption(o.cleft, vg, "--cleft", needs);
  requireOption(o.halfVessel, vg, "--half-vessel", needs);
  requireOption(o.hybrid, vg, "--hybrid-cpr", needs);
  if (!vg) return std::nullopt;

  VesselGlyphRecipe recipe;
  recipe.centerlines = std::filesystem::absolute(o.centerlines).lexically_normal().string();
  VesselGlyphSettings& settings = recipe.settings;
  if (o.focus) settings.focus = parseFocusSpec(*o.focus);
  if (o.context) parseContextSpec(*o.context, settings);
  settings.cleft = o.cleft;
  settings.halfVessel = o.halfVessel;
  recipe.focusTf = loadPresetOrFile(o.focusTf.value_or(baseTf));
  recipe.contextTf =
      o.contextTf ? loadPresetOrFile(*o.contextTf) : followingContextTf(loadPresetOrFile(baseTf));
  if (o.outside && *o.outside != "clip") recipe.outsideTf = loadPresetOrFile(*o.outside);
  return recipe;
}

std::optional<HybridCprRecipe> hybridCprRecipe(const VesselGlyphCliOptions& o) {
  const char* needs = "--hybrid-cpr";
  requireOption(o.hybridPath.has_value(), o.hybrid, "--hybrid-path", needs);
  requireOption(o.transitionMm.has_value(), o.hybrid, "--transition", needs);
  requireOption(o.cprWindow.has_value() || o.cprLevel.has_value(), o.hybrid, "--cpr-window/--cpr-level",
                needs);
  if (o.cprWindow.has_value() != o.cprLevel.has_value())
    throw std::invalid_argument("--cpr-window and --cpr-level go together");
  if (!o.hybrid) return std::nullopt;
  HybridCprRecipe hybrid;
  hybrid.path = o.hybridPath.value_or("all");
  hybrid.transitionMm = o.transitionMm.value_or(0);
  if (o.cprWindow) hybrid.grey = WindowLevel{*o.cprWindow, *o.cprLevel};
  return hybrid;
}

}  // namespace angio
