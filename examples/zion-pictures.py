#!/usr/bin/env python3
"""The README's Zion pictures from the example's store and quicklooks.

Run after `maquette run examples/texture-zion.json` (python3 with GDAL and numpy, e.g. Debian's
python3-gdal and python3-numpy):

    python3 examples/zion-pictures.py build/bin/maquette

docs/zion-texture.jpg: the calibrated scene, the texture at 8.8 m and the summer radiation, the
example's PNG quicklooks side by side. docs/zion-closeup.jpg: the scene at 30 m, the texture at
8.8 m (albedo: what the 3D Tiles carry) and the same texture lit as the viewer drapes it, each
resampled to 8.8 m in UTM zone 12N. The lit texture is the albedo times the inverse of the
C-correction that texture.fit removed from the scene, (max(cos i, m) + c) / (sin(altitude) + c),
i the incidence of the scene's sun on the texture's own 8.8 m height: the shading the scene's
colours were divided by, put back on the finer relief. The sun (the hillshade's azimuth and
altitude), c and the floor m are the example's (texture-zion.json; m the operator's default
when the example leaves it out, from `maquette modules --json`).
"""
import json
import math
import os
import subprocess
import sys
import tempfile

import numpy as np
from osgeo import gdal

HERE = os.path.dirname(os.path.abspath(__file__))
DOCS = os.path.join(HERE, "..", "docs")
STORE = os.path.join(HERE, "zion.mqt")
CLOSEUP_BBOX = ["-112.93", "37.22", "-112.898", "37.252"]  # W S E N
HEIGHT, GAP = 400, 10  # panel height and the white gap between panels, pixels


def illumination(maquette):
    """The example's sun (azimuth, altitude: its hillshade's), c of texture.fit's C-correction
    and its floor of cos i."""
    with open(os.path.join(HERE, "texture-zion.json")) as f:
        steps = json.load(f)["steps"]
    derive = next(s["params"] for s in steps if s["outputs"].get("hillshade") == "hillshade")
    fit = next(s["params"] for s in steps if s["op"] == "texture.fit")
    if "min_incidence_cos" not in fit:
        modules = json.loads(subprocess.run([maquette, "modules", "--json"], check=True,
                                            capture_output=True, text=True).stdout)
        schema = next(o["params"] for m in modules for o in m["operators"]
                      if o["name"] == "texture.fit")
        fit["min_incidence_cos"] = schema["properties"]["min_incidence_cos"]["default"]
    assert fit["sun_altitude"] == derive["altitude"], "the fit's sun is the hillshade's"
    return derive["azimuth"], derive["altitude"], fit["c_correction"], fit["min_incidence_cos"]


def scaled(rgb, height):
    """An RGB array (3, h, w) resampled to `height` rows (aspect kept, averaging)."""
    src = gdal.GetDriverByName("MEM").Create("", rgb.shape[2], rgb.shape[1], 3, gdal.GDT_Byte)
    for b in range(3):
        src.GetRasterBand(b + 1).WriteArray(rgb[b])
    width = round(rgb.shape[2] * height / rgb.shape[1])
    out = gdal.Translate("", src, format="MEM", width=width, height=height, resampleAlg="average")
    return out.ReadAsArray()


def side_by_side(panels, path):
    """Panels (3, h, w) scaled to HEIGHT rows, GAP white columns between them, as a JPEG."""
    panels = [scaled(p, HEIGHT) for p in panels]
    width = sum(p.shape[2] for p in panels) + GAP * (len(panels) - 1)
    canvas = np.full((3, HEIGHT, width), 255, np.uint8)
    x = 0
    for p in panels:
        canvas[:, :, x : x + p.shape[2]] = p
        x += p.shape[2] + GAP
    mem = gdal.GetDriverByName("MEM").Create("", width, HEIGHT, 3, gdal.GDT_Byte)
    for b in range(3):
        mem.GetRasterBand(b + 1).WriteArray(canvas[b])
    gdal.GetDriverByName("JPEG").CreateCopy(path, mem, options=["QUALITY=88"])


def exported(maquette, layer, directory):
    """The close-up of `layer` in UTM zone 12N at 8.8 m, as an array (bands, rows, columns)."""
    out = os.path.join(directory, layer + ".tif")
    subprocess.run([maquette, "-q", "export", "gtiff", STORE, out, "--layer", layer, "--bbox",
                    *CLOSEUP_BBOX, "--crs", "EPSG:32612", "--resolution", "8.8"], check=True)
    ds = gdal.Open(out)
    return ds.ReadAsArray().astype(np.float64), ds.GetGeoTransform()


def inner_box(valid):
    """Rows [top, bottom) and columns [left, right) of a box of `valid` pixels only: the border
    row or column with the most invalid pixels dropped until none is left (the bbox's corners
    in UTM lie beyond the exported lon/lat box)."""
    top, bottom, left, right = 0, valid.shape[0], 0, valid.shape[1]
    while True:
        box = valid[top:bottom, left:right]
        sides = [(box[0] == 0).sum(), (box[-1] == 0).sum(), (box[:, 0] == 0).sum(),
                 (box[:, -1] == 0).sum()]
        worst = int(np.argmax(sides))
        if sides[worst] == 0:
            return top, bottom, left, right
        if worst == 0:
            top += 1
        elif worst == 1:
            bottom -= 1
        elif worst == 2:
            left += 1
        else:
            right -= 1


def lit(albedo, height, transform, light):
    """The albedo lit by the scene's sun on `height` (the inverse C-correction, module doc);
    `light` as illumination() returns it."""
    sun_azimuth, sun_altitude, c_correction, min_cos = light
    dz_drow, dz_dcol = np.gradient(height)
    dz_dx = dz_dcol / transform[1]   # east
    dz_dy = dz_drow / transform[5]   # north (the rows' step is negative)
    az, alt = math.radians(sun_azimuth), math.radians(sun_altitude)
    sun = (math.sin(az) * math.cos(alt), math.cos(az) * math.cos(alt), math.sin(alt))
    cos_i = (-dz_dx * sun[0] - dz_dy * sun[1] + sun[2]) / np.sqrt(dz_dx**2 + dz_dy**2 + 1)
    factor = (np.maximum(cos_i, min_cos) + c_correction) / (math.sin(alt) + c_correction)
    factor = np.where(np.isfinite(factor), factor, 1)
    return np.clip(albedo * factor, 0, 255)


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    maquette = sys.argv[1]
    quicklooks = [os.path.join(HERE, "zion-output", n)
                  for n in ("landsat.png", "texture.png", "radiation.png")]
    side_by_side([gdal.Open(q).ReadAsArray()[:3] for q in quicklooks],
                 os.path.join(DOCS, "zion-texture.jpg"))
    with tempfile.TemporaryDirectory() as directory:
        scene, _ = exported(maquette, "rgb", directory)
        albedo, _ = exported(maquette, "texture_fine", directory)
        height, transform = exported(maquette, "texture_height", directory)
    rows = min(a.shape[-2] for a in (scene, albedo, height))
    cols = min(a.shape[-1] for a in (scene, albedo, height))
    scene, albedo, height = scene[:, :rows, :cols], albedo[:, :rows, :cols], height[:rows, :cols]
    top, bottom, left, right = inner_box((scene.sum(0) > 0) & (albedo.sum(0) > 0))
    panels = [scene, albedo, lit(albedo, height, transform, illumination(maquette))]
    side_by_side([np.clip(p[:, top:bottom, left:right], 0, 255).astype(np.uint8) for p in panels],
                 os.path.join(DOCS, "zion-closeup.jpg"))


if __name__ == "__main__":
    main()
