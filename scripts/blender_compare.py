# Compares glint's renders of the Blender exports with Cycles' references over the visible
# surfaces (the pixels Cycles' transparent film marks opaque, alpha > 0.999): relative MSE as
# `glint compare` computes it, (t - r)^2 / (r^2 + 0.01) averaged over pixels and channels,
# and each channel's mean relative to Cycles'. Run inside Blender (it reads the EXRs):
#   blender -b --factory-startup --python scripts/blender_compare.py -- OUTDIR SCENE...
# Prints one Markdown table row per (scene, format) found as OUTDIR/SCENE-glint-FORMAT.exr.
import os
import sys

import bpy

argv = sys.argv[sys.argv.index("--") + 1:]
OUT, SCENES = argv[0], argv[1:]


def pixels(path):
    img = bpy.data.images.load(path)
    data = list(img.pixels)
    w, h = img.size
    bpy.data.images.remove(img)
    return data, w, h


print("| scene | file | relative MSE | R mean | G mean | B mean | Cycles means (R, G, B) |")
print("|---|---|---|---|---|---|---|")
for scene in SCENES:
    ref, w, h = pixels(os.path.join(OUT, scene + "-cycles.exr"))
    for fmt in ("glb", "obj", "ply"):
        path = os.path.join(OUT, "%s-glint-%s.exr" % (scene, fmt))
        if not os.path.exists(path):
            continue
        test, tw, th = pixels(path)
        if (tw, th) != (w, h):
            print("| %s | %s | size %dx%d, Cycles %dx%d | | | | |" % (scene, fmt, tw, th, w, h))
            continue
        n, rel = 0, 0.0
        sums, ref_sums = [0.0] * 3, [0.0] * 3
        for i in range(w * h):
            if ref[4 * i + 3] <= 0.999:
                continue
            n += 1
            for c in range(3):
                t, r = test[4 * i + c], ref[4 * i + c]
                rel += (t - r) ** 2 / (r * r + 1e-2)
                sums[c] += t
                ref_sums[c] += r
        rel /= 3 * max(n, 1)
        ratios = ["%+.1f %%" % (100 * (sums[c] / ref_sums[c] - 1)) if ref_sums[c] > 0 else "-"
                  for c in range(3)]
        print("| %s | %s | %.4f | %s | %s | %s | %.3f, %.3f, %.3f |" % (
            scene, fmt, rel, ratios[0], ratios[1], ratios[2],
            ref_sums[0] / max(n, 1), ref_sums[1] / max(n, 1), ref_sums[2] / max(n, 1)))
