#!/usr/bin/python3
"""Bench only: VTK's CPU raycaster (vtkFixedPointVolumeRayCastMapper, 3D Slicer's CPU path) vs angioray.

Usage (through the wrapper, which provides an X server when there is none):
  build/angioray phantom /tmp/real256.nrrd --size 256x256x600   # or any axis-aligned short NRRD
  bench/vtk_ratio.sh --volume PATH.nrrd [--tf PRESET|FILE] [--angles N] [--levels L ...]
                     [--images DIR] [--angioray BUILD/angioray]
Needs Debian's python3-vtk9 (apt-get install python3-vtk9); not part of scripts/setup.sh or CI.

For every level, VTK renders the same volume, TF, rays, sample distance and interpolation as
angioray (rendering model: View, Sampling; levels of core/render_params.cpp and
bench/frame_bench.cpp). The level's parameters and the TF are not repeated here: they are read
from the sidecar of `angioray render --angle 0` at that level, which also gives the comparison image.
Then `angioray bench` times angioray and VTK renders the same N angles; the table gives the ratio.
"""
import argparse
import gzip
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time

import vtk

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# The levels of `angioray bench` (bench/frame_bench.cpp levels()) as `angioray render` flags.
LEVELS = {
    "fast": ["--quality", "fast"],  # angioray: mean filter; VTK has none, it gets nearest
    "medium": ["--quality", "medium"],
    "medium-trilinear": ["--quality", "medium", "--filter", "trilinear"],
    "high": ["--quality", "high"],
}
VTK_FILTER = {"mean": "nearest", "nearest": "nearest", "trilinear": "linear"}


def read_nrrd(path):
    """The NRRDs `angioray phantom` writes: one file, signed 16-bit HU, raw or gzip, axis-aligned."""
    try:
        with open(path, "rb") as f:
            blob = f.read()
    except OSError as error:
        sys.exit(f"{path}: {error.strerror}")
    end = blob.find(b"\n\n")
    if not blob.startswith(b"NRRD") or end < 0:
        sys.exit(f"{path}: not a single-file NRRD")
    fields = {}
    for line in blob[:end].decode("latin-1").splitlines()[1:]:
        if not line.startswith("#") and ": " in line:
            key, value = line.split(": ", 1)
            fields[key.strip()] = value.strip()
    if fields.get("type") not in ("short", "int16", "signed short", "int16_t", "short int"):
        sys.exit(f"{path}: type {fields.get('type')} is not signed 16-bit")
    if fields.get("endian", "little") != "little" or "data file" in fields:
        sys.exit(f"{path}: only little-endian data in the same file is read")
    sizes = [int(s) for s in fields["sizes"].split()]
    if "space directions" in fields:
        vectors = [[float(x) for x in v.strip("()").split(",")] for v in fields["space directions"].split()]
        spacing = [vectors[a][a] for a in range(3)]
        if any(vectors[a][b] != 0 for a in range(3) for b in range(3) if a != b) or min(spacing) <= 0:
            sys.exit(f"{path}: only axis-aligned LPS volumes (positive diagonal space directions) are read")
    else:
        spacing = [float(s) for s in fields["spacings"].split()]
    raw = blob[end + 2:]
    if fields.get("encoding") in ("gzip", "gz"):
        raw = gzip.decompress(raw)
    elif fields.get("encoding") != "raw":
        sys.exit(f"{path}: encoding {fields.get('encoding')} is not read (raw or gzip)")
    importer = vtk.vtkImageImport()
    importer.CopyImportVoidPointer(raw, len(raw))
    importer.SetDataScalarTypeToShort()
    importer.SetNumberOfScalarComponents(1)
    importer.SetWholeExtent(0, sizes[0] - 1, 0, sizes[1] - 1, 0, sizes[2] - 1)
    importer.SetDataExtentToWholeExtent()
    importer.SetDataSpacing(*spacing)
    importer.SetDataOrigin(0, 0, 0)  # voxel centres at index * spacing, as in the volume frame
    importer.Update()
    # HU outside angioray's 12 bits [-1024, 3071] would be clamped by angioray, not by VTK; the
    # phantoms stay inside.
    return importer, sizes, spacing


def view_size(sizes, spacing, isd):
    """angioray's image (core/view_geometry.cpp, axis k): W = ceil(hypot(E_i, E_j) / D), H = ceil(E_k / D)."""
    extent = [(n - 1) * s for n, s in zip(sizes, spacing)]
    pixel = isd * min(spacing)
    return max(1, math.ceil(math.hypot(extent[0], extent[1]) / pixel)), max(1, math.ceil(extent[2] / pixel)), extent


def angioray_render(args, level, out_dir):
    """angioray's image of angle 0 at `level`, and its sidecar (sampling, shading, TF in full)."""
    out = os.path.join(out_dir, f"angioray-{level}.png")
    subprocess.run([args.angioray, "render", args.volume, "--out", out, "--tf", args.tf, "--angle", "0"]
                   + LEVELS[level], check=True, stdout=subprocess.DEVNULL)
    with open(out + ".json") as f:
        return json.load(f)


def angioray_bench(args, work_dir):
    """The "all" row per level (bench/frame_bench.cpp toJson: "frames" rows)."""
    out = os.path.join(work_dir, "angioray-bench.json")
    subprocess.run([args.angioray, "bench", args.volume, "--tf", args.tf, "--angles", str(args.angles),
                    "--no-contributions", "--threads", "2", "--json", out, "--levels"] + args.levels,
                   check=True, stdout=subprocess.DEVNULL)
    with open(out) as f:
        rows = json.load(f)["frames"]
    return {r["level"]: r for r in rows if r["variant"] == "all"}


def vtk_transfer_function(tf):
    colors, opacities = vtk.vtkColorTransferFunction(), vtk.vtkPiecewiseFunction()
    mod = tf.get("modulators", {})
    for p in tf["points"]:
        hu = p["hu"] + mod.get("hu_shift", 0.0)
        colors.AddRGBPoint(hu, *p["color"])
        opacities.AddPoint(hu, min(1.0, p["opacity"] * mod.get("opacity_scale", 1.0)))
    return colors, opacities  # both constant beyond the end points (clamping on), as in angioray


class VtkScene:
    def __init__(self, importer):
        vtk.vtkMultiThreader.SetGlobalMaximumNumberOfThreads(2)
        self.mapper = vtk.vtkFixedPointVolumeRayCastMapper()
        self.mapper.SetInputConnection(importer.GetOutputPort())
        self.mapper.SetNumberOfThreads(2)
        self.mapper.AutoAdjustSampleDistancesOff()  # else VTK picks its own distances per frame
        self.mapper.LockSampleDistanceToInputSpacingOff()
        self.volume = vtk.vtkVolume()
        self.volume.SetMapper(self.mapper)
        self.renderer = vtk.vtkRenderer()  # black background, two-sided lighting: |n.l|
        self.renderer.AddVolume(self.volume)
        # The rendering model's headlight: s = ka + kd |g.d| / |g|. VTK's automatic headlight has an
        # ambient colour of 0, which would drop the ka term (the image came out ~40 % darker).
        light = vtk.vtkLight()
        light.SetLightTypeToHeadlight()
        light.SetAmbientColor(1, 1, 1)
        self.renderer.AddLight(light)
        self.renderer.GetActiveCamera().ParallelProjectionOn()
        self.window = vtk.vtkRenderWindow()
        self.window.SetOffScreenRendering(1)  # an FBO: the window may be larger than the X screen
        self.window.AddRenderer(self.renderer)

    def setup(self, sidecar, sizes, spacing):
        """One level: returns VTK's window size and angioray's W x H."""
        sampling, shading = sidecar["sampling"], sidecar["shading"]
        u = min(spacing)
        prop = vtk.vtkVolumeProperty()
        colors, opacities = vtk_transfer_function(sidecar["tf"])
        prop.SetColor(colors)
        prop.SetScalarOpacity(opacities)
        # angioray's TF opacity is per voxel unit u: alpha = 1 - (1 - a)^(delta / u); VTK's is
        # 1 - (1 - a)^(SampleDistance / ScalarOpacityUnitDistance).
        prop.SetScalarOpacityUnitDistance(u)
        if VTK_FILTER[sampling["filter"]] == "linear":
            prop.SetInterpolationTypeToLinear()
        else:
            prop.SetInterpolationTypeToNearest()
        prop.SetShade(1 if shading["enabled"] else 0)
        prop.SetAmbient(shading["ka"])
        prop.SetDiffuse(shading["kd"])
        prop.SetSpecular(0.0)  # the rendering model has no specular term
        self.volume.SetProperty(prop)
        self.mapper.SetSampleDistance(sampling["osd"] * u)  # delta, mm
        # One window pixel = u mm, so ImageSampleDistance = isd casts a ray every D = isd * u mm,
        # W x H rays as angioray (within a pixel: VTK rounds the window, ray grid offsets differ).
        isd = sampling["isd"]
        width, height, self.extent = view_size(sizes, spacing, isd)
        self.mapper.SetImageSampleDistance(isd)
        window = (max(1, round(width * isd)), max(1, round(height * isd)))
        self.window.SetSize(*window)
        self.renderer.GetActiveCamera().SetParallelScale(window[1] * u / 2)
        return window, (width, height)

    def look(self, degrees):
        """The rendering model's view about k: d = cos(t) e_j - sin(t) e_i, up e_k (VTK's right,
        d x up, is then r = cos(t) e_i + sin(t) e_j)."""
        t = math.radians(degrees)
        d = (-math.sin(t), math.cos(t), 0.0)
        centre = [e / 2 for e in self.extent]
        far = 2 * math.hypot(*self.extent)
        camera = self.renderer.GetActiveCamera()
        camera.SetFocalPoint(*centre)
        camera.SetPosition(*(c - far * x for c, x in zip(centre, d)))
        camera.SetViewUp(0, 0, 1)
        self.renderer.ResetCameraClippingRange()  # the mapper clips rays to the near/far planes

    def render_ms(self, degrees):
        """Wall and CPU ms of one full render (a new camera: VTK casts every ray again)."""
        self.look(degrees)
        wall, cpu = time.perf_counter(), time.process_time()
        self.window.Render()
        return 1000 * (time.perf_counter() - wall), 1000 * (time.process_time() - cpu)

    def save_png(self, path):
        self.render_ms(0)
        grab = vtk.vtkWindowToImageFilter()
        grab.SetInput(self.window)
        grab.ReadFrontBufferOff()
        grab.Update()
        writer = vtk.vtkPNGWriter()
        writer.SetFileName(path)
        writer.SetInputConnection(grab.GetOutputPort())
        writer.Write()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--volume", required=True, help="single-file NRRD, signed 16-bit HU")
    parser.add_argument("--tf", default="cta-vessels")
    parser.add_argument("--angles", type=int, default=12)
    parser.add_argument("--levels", nargs="+", choices=list(LEVELS), default=list(LEVELS))
    parser.add_argument("--images", help="write angle 0 of both renderers per level here")
    parser.add_argument("--angioray", default=os.path.join(ROOT, "build", "angioray"))
    args = parser.parse_args()
    if args.angles < 1:
        sys.exit("--angles must be at least 1")
    importer, sizes, spacing = read_nrrd(args.volume)  # first: a bad file fails before any timing

    with tempfile.TemporaryDirectory() as work_dir:
        image_dir = args.images or work_dir
        os.makedirs(image_dir, exist_ok=True)
        sidecars = {level: angioray_render(args, level, image_dir) for level in args.levels}
        print(f"angioray bench: {args.volume}, {args.angles} angles ...", file=sys.stderr)
        ours = angioray_bench(args, work_dir)

    scene = VtkScene(importer)
    lines, rows = [], []
    for level in args.levels:
        sidecar = sidecars[level]
        window, rays = scene.setup(sidecar, sizes, spacing)
        for _ in range(2):  # warm-up: gradients, min-max volume, tables, GL resources
            scene.render_ms(0)
        times = [scene.render_ms(360.0 * n / args.angles) for n in range(args.angles)]
        wall = [w for w, _ in times]
        cpu_per_wall = statistics.median(c / w for w, c in times)
        if args.images:
            scene.save_png(os.path.join(args.images, f"vtk-{level}.png"))
        s, row = sidecar["sampling"], ours[level]
        lines.append(f"  {level}: angioray {rays[0]}x{rays[1]} rays, isd {s['isd']:g}, osd {s['osd']:g},"
                     f" {s['filter']}, ert {s['ert']:g}, cpu/wall {row['median_cpu_ms'] / row['median_ms']:.2f}"
                     f"\n  {'':{len(level)}}  VTK {window[0]}x{window[1]} px window, ImageSampleDistance"
                     f" {s['isd']:g}, SampleDistance {s['osd'] * min(spacing):g} mm,"
                     f" {VTK_FILTER[s['filter']]}, ert 0.992 (fixed), cpu/wall {cpu_per_wall:.2f}")
        vtk_median = statistics.median(wall)
        rows.append((level, row["median_ms"], f"{vtk_median:.1f} ({min(wall):.1f}-{max(wall):.1f})",
                     vtk_median / row["median_ms"]))
        print(f"vtk: {level} {vtk_median:.1f} ms", file=sys.stderr)

    first = sidecars[args.levels[0]]
    shading = first["shading"]
    print(f"volume {args.volume} ({sizes[0]}x{sizes[1]}x{sizes[2]}, spacing "
          f"{'x'.join(f'{s:g}' for s in spacing)} mm); TF {args.tf} ({first['tf'].get('name', '')});"
          f" {args.angles} angles about k; 2 threads; shading {'on' if shading['enabled'] else 'off'},"
          f" ka {shading['ka']:g}, kd {shading['kd']:g}, no specular")
    print("\n".join(lines))
    print(f"{'level':<18}{'angioray ms':>12}  {'VTK ms (min-max)':<26}{'VTK/angioray':>12}")
    for level, ms, vtk_text, ratio in rows:
        print(f"{level:<18}{ms:>12.1f}  {vtk_text:<26}{ratio:>12.1f}")
    if args.images:
        print(f"images: {args.images}/angioray-LEVEL.png (with sidecar) and vtk-LEVEL.png, angle 0")


if __name__ == "__main__":
    main()
