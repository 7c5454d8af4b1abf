// The bad-input catalogue of the command line: every case has one bad flag value (a number that
// is NaN, infinite, out of range or malformed, a value a renderer cannot finish, a name that is
// not one of the choices) and must be refused as tests/support/bad_input_case.h says.
#include <gtest/gtest.h>

#include "tests/support/bad_input_case.h"

namespace angio {
namespace {

using test_support::BadInput;

// The command lines with one bad value each, by subcommand.
const BadInput kFlags[] = {
    // render: the view and the sampling.
    {"render {aorta} --out {dir}/out.png --angle nan", "--angle", "finite"},
    {"render {aorta} --out {dir}/out.png --angle inf", "--angle", "finite"},
    {"render {aorta} --out {dir}/out.png --angle -inf", "--angle", "finite"},
    {"render {aorta} --out {dir}/out.png --angle 12deg", "--angle", "12deg"},
    {"render {aorta} --out {dir}/out.png --isd nan", "--isd", "finite"},
    {"render {aorta} --out {dir}/out.png --isd 0", "--isd", ">="},
    {"render {aorta} --out {dir}/out.png --isd -1", "--isd", ">="},
    {"render {aorta} --out {dir}/out.png --isd 1e-9", "--isd", ">="},
    {"render {aorta} --out {dir}/out.png --isd 0.001", "out.png", "too large"},
    {"render {aorta} --out {dir}/out.png --osd nan", "--osd", "finite"},
    {"render {aorta} --out {dir}/out.png --osd 0", "--osd", ">="},
    {"render {aorta} --out {dir}/out.png --osd 1e-9", "--osd", ">="},
    {"render {aorta} --out {dir}/out.png --osd inf", "--osd", "finite"},
    {"render {aorta} --out {dir}/out.png --ert nan", "--ert", "finite"},
    {"render {aorta} --out {dir}/out.png --ert 5", "--ert", "[0, 1]"},
    {"render {aorta} --out {dir}/out.png --ert -0.5", "--ert", "[0, 1]"},
    {"render {aorta} --out {dir}/out.png --ka nan", "--ka", "finite"},
    {"render {aorta} --out {dir}/out.png --ka 11", "--ka", "[0, 10]"},
    {"render {aorta} --out {dir}/out.png --kd inf", "--kd", "finite"},
    {"render {aorta} --out {dir}/out.png --kd -1", "--kd", "[0, 10]"},
    {"render {aorta} --out {dir}/out.png --mip --window 0", "--window", "> 0"},
    {"render {aorta} --out {dir}/out.png --mip --window nan", "--window", "finite"},
    {"render {aorta} --out {dir}/out.png --mip --level nan", "--level", "finite"},
    {"render {aorta} --out {dir}/out.png --mip --level -inf", "--level", "finite"},
    {"render {aorta} --out {dir}/out.png --axis x", "--axis", "x"},
    {"render {aorta} --out {dir}/out.png --filter cubic", "--filter", "cubic"},
    {"render {aorta} --out {dir}/out.png --quality ultra", "--quality", "ultra"},
    {"render {aorta} --out {dir}/out.png --shading maybe", "--shading", "maybe"},
    // render: the image window, crop, clip plane and slab (comma lists).
    {"render {aorta} --out {dir}/out.png --image-window nan,1,2,3", "--image-window", "nan"},
    {"render {aorta} --out {dir}/out.png --image-window 1,2", "--image-window", "1,2"},
    {"render {aorta} --out {dir}/out.png --image-window 5,1,0,1", "image window", "left < right"},
    {"render {aorta} --out {dir}/out.png --crop 0,0,0,nan,10,10", "--crop", "nan"},
    {"render {aorta} --out {dir}/out.png --crop 0,0,0", "--crop", "0,0,0"},
    {"render {aorta} --out {dir}/out.png --clip 0,0,0,0,0,inf", "--clip", "inf"},
    {"render {aorta} --out {dir}/out.png --slab 0,nan", "--slab", "nan"},
    // render: VesselGlyph numbers.
    {"render {aorta} --out {dir}/out.png --transition nan", "--transition", "finite"},
    {"render {aorta} --out {dir}/out.png --transition -2", "--transition", ">= 0"},
    {"render {aorta} --out {dir}/out.png --cpr-window 0", "--cpr-window", "> 0"},
    {"render {aorta} --out {dir}/out.png --cpr-level nan", "--cpr-level", "finite"},
    // cpr.
    {"cpr {aorta} --centerlines {cl} --out {dir}/out.png --width nan", "--width", "finite"},
    {"cpr {aorta} --centerlines {cl} --out {dir}/out.png --width 0", "--width", "> 0"},
    {"cpr {aorta} --centerlines {cl} --out {dir}/out.png --pixel inf", "--pixel", "finite"},
    {"cpr {aorta} --centerlines {cl} --out {dir}/out.png --pixel -0.5", "--pixel", "> 0"},
    {"cpr {aorta} --centerlines {cl} --out {dir}/out.png --window nan --level 100", "--window",
     "finite"},
    {"cpr {aorta} --centerlines {cl} --out {dir}/out.png --window 100 --level inf", "--level", "finite"},
    {"cpr {aorta} --centerlines {cl} --out {dir}/out.png --bench-length nan", "--bench-length",
     "finite"},
    // gui (parsed before any window opens).
    {"gui {aorta} --headless --timeout nan", "--timeout", "finite"},
    {"gui {aorta} --headless --timeout 0", "--timeout", "> 0"},
    {"gui {aorta} --quit-after -1", "--quit-after", ">= 0"},
    {"gui {aorta} --motion-budget nan", "--motion-budget", "finite"},
    {"gui {aorta} --motion-budget 5000", "--motion-budget", "[0, 1000]"},
    // render: files named by flags, outputs, choices.
    {"render {aorta} --out {dir}/out.png --tf no-such-preset", "no-such-preset",
     "no such preset or file"},
    {"render {aorta} --out {dir}/out.png --labels {dir}/missing.nrrd", "missing.nrrd", "does not exist"},
    {"render {aorta} --out {dir}/out.png --hide kidney", "--hide", "needs --labels"},
    {"render --params {dir}/missing.json --out {dir}/out.png", "missing.json", "no such"},
    {"render {aorta} --out {dir}/out.bmp", "out.bmp", "format"},
    {"render {aorta} --out {dir}/no/such/out.png", "out.png", "folder does not exist"},
    {"render {aorta} --out {dir}", "is a folder", "cannot write a file over it"},
    {"render {dir}/missing.mha --out {dir}/out.png", "missing.mha", "does not exist"},
    {"render {aorta} --out {dir}/out.png --clip-facing nan", "--clip-facing", "nan"},
    {"render {aorta} --out {dir}/out.png --crop 10,0,0,5,10,10", "crop", "min"},
    // VesselGlyph flags.
    {"render {aorta} --out {dir}/out.png --centerlines {cl} --vg-focus blob", "--vg-focus", "blob"},
    {"render {aorta} --out {dir}/out.png --centerlines {cl} --vg-focus circle:radius=nan", "--vg-focus",
     "nan"},
    {"render {aorta} --out {dir}/out.png --centerlines {cl} --vg-context circle:radius=-2",
     "--vg-context", "radius"},
    {"render {aorta} --out {dir}/out.png --centerlines {cl} --vg-focus circle:radius=3 --focus-tf nope",
     "nope", "no such preset or file"},
    {"render {aorta} --out {dir}/out.png --centerlines {cl} --vg-focus circle:radius=3 --vg-outside "
     "maybe",
     "maybe", "no such preset or file"},
    {"render {aorta} --out {dir}/out.png --centerlines {cl} --hybrid-cpr --hybrid-path nope", "nope",
     "path"},
    {"render {aorta} --out {dir}/out.png --vg-focus circle:radius=3", "--vg-focus", "--centerlines"},
    // cpr.
    {"cpr {aorta} --centerlines {cl} --out {dir}/out.png --path nope", "nope", "path"},
    {"cpr {aorta} --centerlines {cl} --out {dir}/out.png --mode bent", "--mode", "bent"},
    {"cpr {aorta} --centerlines {cl} --out {dir}/out.png --angle nan", "--angle", "finite"},
    {"cpr {aorta} --centerlines {cl} --out {dir}/out.png --window-preset sun", "--window-preset", "sun"},
    {"cpr {aorta} --centerlines {cl} --out {dir}/out.png --resampler spline", "--resampler", "spline"},
    {"cpr {aorta} --centerlines {cl} --out {dir}/out.png --pixel 1e-9", "pixel size", "too small"},
    {"cpr {aorta} --centerlines {dir}/missing.csv --out {dir}/out.png", "missing.csv", "no such file"},
    {"cpr {aorta} --out {dir}/out.png", "--centerlines", "required"},
    // phantom.
    {"phantom {dir}/p.mha --size 0x0x0", "size '0x0x0'", "8..4096"},
    {"phantom {dir}/p.mha --size 100000x100000x100000", "size '100000x100000x100000'", "8..4096"},
    {"phantom {dir}/p.mha --size 64x64", "size '64x64'", "IxJxK"},
    {"phantom {dir}/p.mha --size nanxnanxnan", "size 'nanxnanxnan'", "IxJxK"},
    {"phantom {dir}/p.mha --seed x", "--seed", "x"},
    {"phantom {dir}/p.mha --centerlines {dir}/missing/dir/c.csv", "c.csv", "folder does not exist"},
    {"phantom {dir}/p.mha --labels {dir}/missing/l.nrrd", "l.nrrd", "folder does not exist"},
    {"phantom {dir}/p.xyz", "p.xyz", "format"},
    {"phantom {dir}/out.png.json --size 32x32x32", "out.png.json", "format"},
    // segment.
    {"segment {aorta} --out {dir}/labels.png", "labels.png", "format"},
    {"segment {aorta} --labels {dir}/missing.nrrd --out {dir}/l.nrrd", "missing.nrrd", "does not exist"},
    {"segment {aorta} --centerlines {dir}/missing.vtp --out {dir}/l.nrrd", "missing.vtp",
     "no such file"},
    {"segment {aorta} --out {dir}/missing/l.nrrd", "l.nrrd", "folder does not exist"},
    // trace.
    {"trace {aorta} --points 1,2 --out {dir}/t.csv", "--points", "1,2"},
    {"trace {aorta} --points 'nan,0,0;1,1,1' --out {dir}/t.csv", "--points", "nan"},
    {"trace {aorta} --voxels '80,60,10;99999,0,0' --out {dir}/t.csv", "--voxels",
     "point 2: the point lies outside"},
    {"trace {aorta} --points '-218,-316,24;-218,-315,25' --tissue-hu nan --out {dir}/t.csv",
     "--tissue-hu", "finite"},
    {"trace {aorta} --points '-218,-316,24;-218,-315,25' --calcium-hu inf --out {dir}/t.csv",
     "--calcium-hu", "finite"},
    {"trace {aorta} --points '-218,-316,24;-218,-315,25' --step 0 --out {dir}/t.csv", "--step",
     "between 0.1 and 5"},
    {"trace {aorta} --points '-218,-316,24;-218,-315,25' --step nan --out {dir}/t.csv", "--step",
     "finite"},
    {"trace {aorta} --points '-218,-316,24;-218,-315,25' --out {dir}/t.txt", "t.txt", "format"},
    {"trace {aorta} --out {dir}/t.csv", "--points", "--voxels"},
    // bench.
    {"bench --size 0x0x0", "size '0x0x0'", "8..4096"},
    {"bench --angles 0", "--angles", "0"},
    {"bench --threads -1", "--threads", "-1"},
    {"bench --levels ultra", "--levels", "ultra"},
    {"bench --tf nope", "nope", "no such preset or file"},
    {"bench {dir}/missing.nrrd", "missing.nrrd", "does not exist"},
    // demo and info.
    {"demo --size 1x1", "size '1x1'", "IxJxK"},
    {"demo --out-dir {dir}/out.png", "out.png", "cannot be made a folder"},
    {"info {dir}/missing.nii", "missing.nii", "does not exist"},
    {"info {aorta} --tf nope", "nope", "no such preset or file"},
    {"info {aorta} --labels {dir}/missing.nrrd", "missing.nrrd", "does not exist"},
    // gui (parsed before any window opens).
    {"gui --headless --phantom-size 8x8", "size '8x8'", "IxJxK"},
    {"gui {aorta} --headless --size 0x0", "window size '0x0'", "320x240"},
    {"gui {aorta} --headless --angle nan", "--angle", "finite"},
    {"gui {aorta} --headless --axis q", "--axis", "q"},
    {"gui {aorta} --headless --tf nope", "nope", "no such preset or file"},
    {"gui {aorta} --headless --script {dir}/missing.json", "missing.json", "cannot"},
    {"gui {aorta} --headless --session {dir}/missing.json", "missing.json", "does not exist"},
    {"gui {aorta} --headless --screenshot {dir}/missing/s.png", "s.png", "does not exist"},
    {"frobnicate", "frobnicate", "frobnicate"},
};

class BadFlags : public test_support::BadInputCatalogue {};

TEST_P(BadFlags, EndWithOneLineNamingTheFlagAndLeaveTheFilesAlone) { expectCleanRefusal(GetParam()); }

INSTANTIATE_TEST_SUITE_P(CommandLine, BadFlags, ::testing::ValuesIn(kFlags), test_support::caseName);

}  // namespace
}  // namespace angio
