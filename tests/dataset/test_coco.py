"""`urdfsnap dataset`'s COCO file read by a reader written here from COCO's published formats, not
from urdfsnap's writer: the RLE strings decoded as COCO's maskApi (rleFrString, rleDecode) reads
them, the label images decoded by a PNG reader of its own (zlib and the five row filters), and each
annotation's mask, bbox and area compared with the label image's pixels. Run by pytest (Debian's
python3-pytest, python3-numpy) with URDFSNAP_BINARY naming the binary.
"""
import json
import os
import pathlib
import struct
import subprocess
import zlib

import numpy as np
import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
MRM = ROOT / "models" / "mrm_description" / "urdf" / "mrm.urdf"


def read_png(path):
    """The samples of a non-interlaced greyscale or RGB PNG (8 or 16 bits) as an array of rows."""
    data = pathlib.Path(path).read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, idat = 8, b""
    while pos < len(data):
        (length,) = struct.unpack(">I", data[pos:pos + 4])
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert interlace == 0
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    channels = {0: 1, 2: 3}[colour]
    bpp = channels * depth // 8   # bytes per pixel, the filters' distance
    stride = width * bpp
    raw = zlib.decompress(idat)
    assert len(raw) == height * (stride + 1)
    rows = np.zeros((height, stride), dtype=np.int32)
    previous = np.zeros(stride, dtype=np.int32)
    for y in range(height):
        kind = raw[y * (stride + 1)]
        line = np.frombuffer(raw, dtype=np.uint8, count=stride, offset=y * (stride + 1) + 1).astype(np.int32)
        if kind == 0:
            out = line
        elif kind == 2:
            out = (line + previous) & 255
        else:   # Sub, Average, Paeth depend on the pixel to the left: byte by byte
            out = np.zeros(stride, dtype=np.int32)
            for i in range(stride):
                left = out[i - bpp] if i >= bpp else 0
                up = previous[i]
                upleft = previous[i - bpp] if i >= bpp else 0
                if kind == 1:
                    predicted = left
                elif kind == 3:
                    predicted = (left + up) // 2
                else:
                    p = left + up - upleft
                    pa, pb, pc = abs(p - left), abs(p - up), abs(p - upleft)
                    predicted = left if pa <= pb and pa <= pc else up if pb <= pc else upleft
                out[i] = (line[i] + predicted) & 255
        rows[y] = out
        previous = out
    if depth == 16:
        rows = rows[:, 0::2] * 256 + rows[:, 1::2]
    return rows.reshape(height, width, channels) if channels > 1 else rows


def rle_counts(text):
    """COCO maskApi's rleFrString: 5 bits a character (offset 48), 0x20 for more, 0x10 the sign of
    the last, and from the fourth count on each one stored as its difference from two counts back."""
    counts, pos = [], 0
    while pos < len(text):
        value, shift, more = 0, 0, True
        while more:
            c = ord(text[pos]) - 48
            value |= (c & 0x1F) << shift
            more = bool(c & 0x20)
            pos += 1
            shift += 5
            if not more and c & 0x10:
                value |= -1 << shift
        if len(counts) > 2:
            value += counts[-2]
        counts.append(value)
    return counts


def rle_mask(segmentation):
    """COCO maskApi's rleDecode: runs alternating 0 and 1, starting with 0, down the columns."""
    height, width = segmentation["size"]
    counts = segmentation["counts"]
    if isinstance(counts, str):
        counts = rle_counts(counts)
    assert all(c >= 0 for c in counts) and sum(counts) == height * width
    flat = np.zeros(height * width, dtype=bool)
    pos = 0
    for i, count in enumerate(counts):
        flat[pos:pos + count] = i % 2 == 1
        pos += count
    return flat.reshape(width, height).T


@pytest.fixture(scope="module")
def dataset(tmp_path_factory):
    folder = tmp_path_factory.mktemp("coco")
    binary = os.environ.get("URDFSNAP_BINARY", str(ROOT / "build" / "urdfsnap"))
    subprocess.run([binary, "dataset", str(MRM), "-o", str(folder), "--count", "4", "--seed", "7",
                    "--size", "320x240", "--quiet"], check=True)
    return folder, json.loads((folder / "annotations.json").read_text())


def test_the_rle_reader_reads_a_mask_worked_by_hand():
    # a 3x3 mask, column-major: column 0 empty, column 1 set, column 2 its top and bottom pixels:
    # counts [3, 4, 1, 1], the fourth stored as 1 - 4 = -3 ("M": 29 + 48, the sign bit 0x10 set)
    assert rle_counts("341M") == [3, 4, 1, 1]
    assert rle_mask({"size": [3, 3], "counts": "341M"}).astype(int).tolist() == [[0, 1, 1], [0, 1, 0], [0, 1, 1]]


def test_every_annotation_is_its_links_pixels(dataset):
    folder, coco = dataset
    links = {c["id"]: c["name"] for c in coco["categories"] if c["supercategory"] == "link"}
    (robot,) = [c["id"] for c in coco["categories"] if c["name"] == "robot"]
    by_image = {}
    for a in coco["annotations"]:
        by_image.setdefault(a["image_id"], []).append(a)
    assert len(coco["images"]) == 4
    for image in coco["images"]:
        labels = read_png(folder / image["labels_file"])
        assert labels.shape == (image["height"], image["width"])
        annotations = by_image[image["id"]]
        seen = set(np.unique(labels)) - {0}
        # one annotation per link in the picture, and one for the whole robot
        assert sorted(a["category_id"] for a in annotations) == sorted(list(seen) + [robot])
        for a in annotations:
            expected = labels != 0 if a["category_id"] == robot else labels == a["category_id"]
            assert a["category_id"] == robot or a["category_id"] in links
            mask = rle_mask(a["segmentation"])
            assert a["segmentation"]["size"] == [image["height"], image["width"]]
            assert np.array_equal(mask, expected), (image["id"], a["category_id"])
            assert a["area"] == int(expected.sum())
            ys, xs = np.nonzero(expected)
            assert a["bbox"] == [xs.min(), ys.min(), xs.max() - xs.min() + 1, ys.max() - ys.min() + 1]
            assert a["iscrowd"] == 0


def test_keypoints_carry_cocos_visibility_flags(dataset):
    folder, coco = dataset
    (category,) = [c for c in coco["categories"] if c["name"] == "robot"]
    for a in coco["annotations"]:
        if a["category_id"] != category["id"]:
            continue
        flat = a["keypoints"]
        assert len(flat) == 3 * len(category["keypoints"])
        triples = [flat[i:i + 3] for i in range(0, len(flat), 3)]
        assert all(v in (0, 1, 2) for _, _, v in triples)
        assert all(x == 0 and y == 0 for x, y, v in triples if v == 0)
        assert a["num_keypoints"] == sum(1 for _, _, v in triples if v > 0)
        image = next(i for i in coco["images"] if i["id"] == a["image_id"])
        for x, y, v in triples:
            if v:   # in the image: OpenCV's pixel coordinates, centres at integers
                assert -0.5 <= x <= image["width"] - 0.5 and -0.5 <= y <= image["height"] - 0.5
