// The main job on the embedded default: the phantom at the three quality levels, as PNGs.
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <system_error>

#include "phantom/phantom.h"
#include "cli/commands.h"
#include "cli/progress_line.h"
#include "cli/size_option.h"
#include "io/image_export.h"
#include "io/input_error.h"
#include "render/recipe_json.h"
#include "render/frame_renderer.h"
#include "io/tf_file.h"

namespace angio {

int runDemo(const DemoOptions& options) {
  PhantomOptions phantomOptions;
  phantomOptions.dims = parseSize(options.size);
  phantomOptions.style = parseStyle(options.style);
  std::error_code error;
  std::filesystem::create_directories(options.outDir, error);  // before the phantom is generated
  if (error || !std::filesystem::is_directory(options.outDir))
    throw InputError(options.outDir, "cannot be made a folder for the images" +
                                         (error ? ": " + error.message() : std::string()));
  Phantom phantom;
  {
    ProgressLine progress("generating phantom " + options.size);
    phantom = generatePhantom(phantomOptions, std::ref(progress));
  }
  const TransferFunction tf = loadPresetOrFile("cta-vessels-bone");
  for (Quality quality : {Quality::fast, Quality::medium, Quality::high}) {
    RenderRecipe recipe;
    recipe.dataset = "phantom " + options.size;
    recipe.tf = tf;
    recipe.quality = quality;
    recipe.params.angleDeg = 20;  // a slight oblique view shows depth better than AP
    recipe.params.sampling = qualitySampling(quality);
    const auto out =
        std::filesystem::path(options.outDir) / ("phantom-" + std::string(toString(quality)) + ".png");
    exportImage(renderRecipe(phantom.volume, {}, recipe), out, renderSidecarMetadata(recipe));
    std::printf("wrote %s\n", out.string().c_str());
  }
  std::printf("no GUI yet: the three quality levels are in %s/\n",
              std::filesystem::absolute(options.outDir).string().c_str());
  return 0;
}

}  // namespace angio
