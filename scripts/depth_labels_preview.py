#!/usr/bin/python3
# Makes the README's picture of the depth and link-label images viewable: the files hold
# millimetres and link numbers (16-bit), which show nearly black as they are. Depth: near is
# bright, nothing is black; labels: one colour per link. Docs tooling (Debian's python3-numpy and
# python3-pil), not part of urdfsnap.
# usage: depth_labels_preview.py COLOUR.png DEPTH.png LABELS.png OUT.png
import sys

import numpy as np
from PIL import Image

colour, depth, labels, out = sys.argv[1:5]
d = np.array(Image.open(depth)).astype(np.float64)
robot = d > 0
near, far = d[robot].min(), d[robot].max()
grey = np.where(robot, 255 - 200 * (d - near) / max(far - near, 1), 0).astype(np.uint8)
palette = np.array([[0, 0, 0], [230, 25, 75], [60, 180, 75], [255, 225, 25], [0, 130, 200],
                    [245, 130, 48], [145, 30, 180], [70, 240, 240], [240, 50, 230], [210, 245, 60]], np.uint8)
l = np.array(Image.open(labels)).astype(np.int64)
coloured = np.where(l[..., None] > 0, palette[1 + (l - 1) % (len(palette) - 1)], 0).astype(np.uint8)
c = np.array(Image.open(colour).convert("RGB"))
Image.fromarray(np.hstack([c, np.stack([grey] * 3, -1), coloured])).save(out)
