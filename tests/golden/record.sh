#!/usr/bin/env bash
# Records the golden corpus: render sidecars (and CPR command lines) that cover every kind of image
# angioray makes, with the dataset paths replaced by placeholders. Run once, on the commit whose
# images are the reference; the hashes are then written by the golden test in record mode:
#   tests/golden/record.sh build/angioray
#   ANGIORAY_GOLDEN_RECORD=1 build/render_tests --gtest_filter='GoldenCorpus.*'
set -euo pipefail
bin=$(realpath "$1")
here=$(cd "$(dirname "$0")" && pwd)
shared=$(realpath "$here/../../../shared/data")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$here/sidecars"
rm -f "$here"/sidecars/*.json

phantom=$work/phantom.nrrd
phantom_cl=$work/phantom.csv
"$bin" phantom "$phantom" --size 96x96x200 --style simple --centerlines "$phantom_cl" >/dev/null
aorta=$shared/aorta.mha
aorta_cl=$shared/aorta-centerlines.csv
aorta_tf=$(realpath "$here/../data/aorta-vmtk-tf.json")

# NAME VOLUME ARGS...: one render whose sidecar becomes NAME.json.
case_render() {
  local name=$1 volume=$2
  shift 2
  "$bin" render "$volume" --out "$work/$name.png" "$@" >/dev/null
  sed -e "s|$phantom_cl|\${PHANTOM_CL}|g" -e "s|$phantom|\${PHANTOM}|g" \
      -e "s|$aorta_cl|\${AORTA_CL}|g" -e "s|$aorta|\${AORTA}|g" \
      -e "s|$work/$name.png|\${OUT}|g" "$work/$name.png.json" >"$here/sidecars/$name.json"
}

vg=(--centerlines "$phantom_cl")
case_render dvr-fast-k30 "$phantom" --quality fast --angle 30
case_render dvr-medium-k30 "$phantom" --quality medium --angle 30
case_render dvr-high-k30 "$phantom" --quality high --angle 30
case_render dvr-medium-i75 "$phantom" --quality medium --axis i --angle 75
case_render dvr-medium-j200 "$phantom" --quality medium --axis j --angle 200
case_render dvr-nearest "$phantom" --quality medium --filter nearest --angle 10
case_render dvr-trilinear "$phantom" --quality medium --filter trilinear --angle 10
case_render dvr-mean "$phantom" --quality medium --filter mean --angle 10
case_render dvr-unshaded "$phantom" --quality medium --shading off --angle 120
case_render dvr-ka-kd-ert "$phantom" --quality medium --ka 0.3 --kd 0.9 --ert 0.9 --angle 300
case_render dvr-reference "$phantom" --quality medium --reference --angle 45
case_render mip-medium "$phantom" --quality medium --mip --window 800 --level 300 --angle 45
case_render mip-trilinear-j "$phantom" --quality medium --mip --filter trilinear --axis j --angle 20
case_render vg-slab "$phantom" --quality medium "${vg[@]}" --angle 30
case_render vg-slab-width "$phantom" --quality medium "${vg[@]}" --vg-context slab:front=10,back=30,width=25 --angle 30
case_render vg-tube "$phantom" --quality medium "${vg[@]}" --vg-context tube:radius=12 --angle 30
case_render vg-none-outside "$phantom" --quality medium "${vg[@]}" --vg-context none --vg-outside cta-vessels --angle 30
case_render vg-focus-mm-cleft "$phantom" --quality medium "${vg[@]}" --vg-focus circle:radius=3mm --cleft --angle 60
case_render vg-half-vessel "$phantom" --quality medium "${vg[@]}" --half-vessel --focus-tf cta-vessels --context-tf soft-tissue-context --angle 90
case_render vg-high-trilinear "$phantom" --quality high "${vg[@]}" --angle 15
case_render hybrid-all-grey "$phantom" --quality medium "${vg[@]}" --hybrid-cpr --angle 30
case_render hybrid-path0-tf "$phantom" --quality medium "${vg[@]}" --hybrid-cpr --hybrid-path 0 --transition 3 --angle 30
case_render hybrid-window "$phantom" --quality medium "${vg[@]}" --hybrid-cpr --cpr-window 600 --cpr-level 200 --angle 210
for angle in 0 90 180 270; do
  case_render "series-$angle" "$phantom" --quality fast --angle "$angle"
done
case_render clip-crop-trilinear "$phantom" --quality medium --filter trilinear --crop 60,340,80,330,250,950 --angle 30
case_render clip-plane-mip "$phantom" --quality medium --mip --clip 200,200,600,0.4,-0.8,0.3 --angle 60
case_render clip-facing-slab-high "$phantom" --quality high --clip-facing -30 --slab 10,120 --angle 15
case_render clip-vg-crop "$phantom" --quality medium "${vg[@]}" --crop 100,300,0,405,300,1000 --angle 30
case_render aorta-dvr "$aorta" --tf "$aorta_tf" --quality medium --axis j --angle 30
case_render aorta-high "$aorta" --tf "$aorta_tf" --quality high --axis j --angle 200
case_render aorta-vg-hybrid "$aorta" --tf "$aorta_tf" --quality medium --axis j --angle 30 \
  --centerlines "$aorta_cl" --hybrid-cpr --transition 2
echo "recorded $(ls "$here/sidecars" | wc -l) sidecars in $here/sidecars"
