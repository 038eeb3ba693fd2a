#!/usr/bin/env python3
"""Fuzzes glint's image readers (src/glint/film/image_codecs.h).

Mutates seed images (PNG and EXR from the repository, a Radiance HDR and a PFM written
here), reads each mutant with `GLINT compare MUTANT MUTANT`, and reports every run that
ended other than with exit 0 or 1 or printed a sanitizer report. Use an ASan/UBSan build:

    scripts/fuzz-image-readers.py build-asan/glint [--per-seed 200] [--seed 1]

Mutants that crash are kept in the working folder as crash_*. docs/robustness.md has the
last run's figures.
"""
import argparse
import os
import random
import struct
import subprocess
import sys
import tempfile

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def seeds():
    width = height = 4
    hdr = b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 4 +X 4\n" + bytes([128, 64, 32, 129]) * 16
    pfm = b"PF\n4 4\n-1.0\n" + struct.pack("<48f", *([0.5] * 48))
    yield "hdr", hdr
    yield "pfm", pfm
    for name in ("examples/textures/checker.png", "examples/gltf/grid.png",
                 "examples/textures/sky.exr"):
        with open(os.path.join(REPO, name), "rb") as f:
            yield name.rsplit(".", 1)[1], f.read()


def mutate(data, rng):
    m = bytearray(data)
    kind = rng.choice(["bytes", "bytes", "truncate", "header"])
    if kind == "bytes":
        for _ in range(rng.randint(1, 8)):
            m[rng.randrange(len(m))] = rng.randrange(256)
    elif kind == "truncate":
        m = m[:rng.randrange(len(m))]
    else:
        for _ in range(rng.randint(1, 4)):
            m[rng.randrange(min(len(m), 64))] = rng.randrange(256)
    return bytes(m)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("glint")
    parser.add_argument("--per-seed", type=int, default=200)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    rng = random.Random(args.seed)
    env = dict(os.environ, ASAN_OPTIONS="detect_leaks=1",
               UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1")
    runs = crashes = 0
    with tempfile.TemporaryDirectory() as folder:
        for ext, data in seeds():
            for i in range(args.per_seed):
                mutant = mutate(data, rng)
                path = os.path.join(folder, "mutant." + ext)
                with open(path, "wb") as f:
                    f.write(mutant)
                result = subprocess.run([args.glint, "compare", path, path], env=env,
                                        capture_output=True, text=True, errors="replace",
                                        timeout=60)
                runs += 1
                if result.returncode not in (0, 1) or "Sanitizer" in result.stderr \
                        or "runtime error" in result.stderr:
                    crashes += 1
                    kept = f"crash_{ext}_{i}.{ext}"
                    with open(kept, "wb") as f:
                        f.write(mutant)
                    print(f"{kept}: exit {result.returncode}\n{result.stderr[-600:]}")
    print(f"{runs} mutants read, {crashes} crashed")
    return 1 if crashes else 0


if __name__ == "__main__":
    sys.exit(main())
