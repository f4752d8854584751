"""How alike two 8-bit images are: PSNR over the RGB channels, and a difference image.

    /usr/bin/python3 scripts/peer/compare.py A.png B.png [DIFF.png] [--gain G]

Prints one line, `psnr_db=.. mean_abs=.. max_abs=.. over_16=..` (mean and largest absolute difference in
8-bit steps, the share of pixels whose largest channel difference exceeds 16 steps). DIFF.png shows
|A - B| per channel times G (default 4), so that differences of a few steps are visible.
Identical images have an infinite PSNR, printed as inf.
"""
import math
import sys

import numpy as np
from PIL import Image


def load(path):
    with Image.open(path) as im:
        return np.asarray(im.convert("RGB"), dtype=np.int32)


def main(argv):
    args = [a for a in argv[1:]]
    gain = 4.0
    if "--gain" in args:
        i = args.index("--gain")
        gain = float(args[i + 1])
        del args[i:i + 2]
    if len(args) not in (2, 3):
        print(__doc__.strip(), file=sys.stderr)
        return 2
    try:
        a, b = load(args[0]), load(args[1])
    except OSError as e:
        print(f"compare: {e}", file=sys.stderr)
        return 1
    if a.shape != b.shape:
        print(f"compare: {args[0]} is {a.shape[1]}x{a.shape[0]} but {args[1]} is {b.shape[1]}x{b.shape[0]}",
              file=sys.stderr)
        return 1
    diff = np.abs(a - b)
    mse = float(np.mean(diff.astype(np.float64) ** 2))
    psnr = math.inf if mse == 0.0 else 10.0 * math.log10(255.0 ** 2 / mse)
    over = float(np.mean(diff.max(axis=2) > 16))
    print(f"psnr_db={psnr:.2f} mean_abs={diff.mean():.3f} max_abs={int(diff.max())} over_16={over:.4f}")
    if len(args) == 3:
        Image.fromarray(np.clip(diff * gain, 0, 255).astype(np.uint8)).save(args[2])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
