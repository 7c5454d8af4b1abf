// The text form of VesselGlyph shapes (vessel/vessel_glyph_spec.h): parsing, errors, round trip.
#include "vessel/vessel_glyph_spec.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

namespace angio {
namespace {

TEST(VesselGlyphSpec, FocusRadiusIsAFactorOrMillimetres) {
  const TubeRadius factor = parseFocusSpec("circle:radius=2.5x");
  EXPECT_EQ(factor.mode, RadiusMode::vesselFactor);
  EXPECT_EQ(factor.value, 2.5);
  for (const std::string spec : {"circle:radius=3", "circle:radius=3mm"}) {
    const TubeRadius constant = parseFocusSpec(spec);
    EXPECT_EQ(constant.mode, RadiusMode::constant) << spec;
    EXPECT_EQ(constant.value, 3.0) << spec;
  }
}

TEST(VesselGlyphSpec, ContextShapes) {
  VesselGlyphSettings settings;
  parseContextSpec("slab:front=12,back=34.5", settings);
  EXPECT_EQ(settings.context, ContextShape::slab);
  EXPECT_EQ(settings.slab.frontMm, 12);
  EXPECT_EQ(settings.slab.backMm, 34.5);
  EXPECT_EQ(settings.slab.halfWidthMm, SlabContext{}.halfWidthMm);
  parseContextSpec("slab:back=1,front=0,width=inf", settings);
  EXPECT_EQ(settings.slab.frontMm, 0);
  EXPECT_TRUE(std::isinf(settings.slab.halfWidthMm));
  parseContextSpec("tube:radius=4x", settings);
  EXPECT_EQ(settings.context, ContextShape::tube);
  EXPECT_EQ(settings.contextTube.mode, RadiusMode::vesselFactor);
  EXPECT_EQ(settings.contextTube.value, 4);
  parseContextSpec("none", settings);
  EXPECT_EQ(settings.context, ContextShape::none);
}

TEST(VesselGlyphSpec, BadSpecsGiveOneLineNamingTheOption) {
  for (const std::string spec :
       {"", "circle", "circle:", "circle:radius", "circle:radius=", "circle:radius=0",
        "circle:radius=-1", "circle:radius=2y", "circle:radius=nan", "circle:radius=1e999",
        "disc:radius=2", "circle:radius=2,radius=3", "circle:radius=2,extra=1"}) {
    try {
      parseFocusSpec(spec);
      ADD_FAILURE() << "accepted '" << spec << "'";
    } catch (const std::invalid_argument& error) {
      const std::string message = error.what();
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
      EXPECT_EQ(message.rfind("--vg-focus '" + spec + "'", 0), 0u) << message;
    }
  }
  VesselGlyphSettings settings;
  for (const std::string spec :
       {"slab", "slab:front=1", "slab:front=1,back=x", "slab:front=1,back=2,width=-3", "tube",
        "tube:radius=0", "none:width=1", "cylinder:radius=2"}) {
    EXPECT_THROW(parseContextSpec(spec, settings), std::invalid_argument) << spec;
  }
}

TEST(VesselGlyphSpec, TextRoundTrips) {
  VesselGlyphSettings settings;
  settings.focus = parseFocusSpec("circle:radius=1.75x");
  EXPECT_EQ(focusSpecText(settings.focus), "circle:radius=1.75x");
  EXPECT_EQ(focusSpecText(parseFocusSpec("circle:radius=3")), "circle:radius=3mm");
  for (const std::string spec : {"slab:front=20,back=5.5,width=40", "slab:front=0,back=20,width=inf",
                                 "tube:radius=12mm", "tube:radius=3x", "none"}) {
    parseContextSpec(spec, settings);
    EXPECT_EQ(contextSpecText(settings), spec);
  }
}

}  // namespace
}  // namespace angio
