#!/usr/bin/env python3
"""Writes the seed corpora of the fuzz targets into tests/fuzz/<target>/ (small files, from the
repository's models and tests, the xacro conformance inputs in ../shared when they are there, and
hand-made PNGs). Regression inputs found by fuzzing live beside them as regression-*; this script
leaves those alone. usage: scripts/make_fuzz_seeds.py"""
import pathlib
import re
import struct
import zlib

ROOT = pathlib.Path(__file__).resolve().parent.parent
FUZZ = ROOT / "tests" / "fuzz"
SHARED = ROOT.parent / "shared"


def seed(target, name, data):
    folder = FUZZ / target
    folder.mkdir(parents=True, exist_ok=True)
    (folder / name).write_bytes(data if isinstance(data, bytes) else data.encode())


def raw_strings(path):
    """The R"(...)" raw strings of a C++ test file."""
    return re.findall(r'R"\((.*?)\)"', path.read_text(), re.S)


def xacro_seeds():
    for path in sorted((ROOT / "models").rglob("*.xacro")):
        seed("xacro_processor", "model-" + path.name, path.read_bytes())
    cases = SHARED / "xacro-conformance" / "cases"
    for path in sorted(cases.glob("*/input.xacro")) if cases.exists() else []:
        seed("xacro_processor", "conformance-" + path.parent.name + ".xacro", path.read_bytes())


def expression_seeds():
    text = (ROOT / "tests" / "xacro" / "expression_test.cpp").read_text()
    # the first string of each {"expression", "result"} case
    for i, match in enumerate(re.finditer(r'\{"((?:[^"\\]|\\.)*)",', text)):
        expression = match.group(1).encode().decode("unicode_escape")
        seed("xacro_expression", "test-%03d" % i, expression)


def urdf_seeds():
    for path in sorted((ROOT / "models").rglob("*.urdf")):
        seed("urdf_loader", "model-" + path.name, path.read_bytes())
    for i, text in enumerate(raw_strings(ROOT / "tests" / "model" / "urdf_loader_test.cpp")):
        seed("urdf_loader", "test-%02d.urdf" % i, text)
    zoo = SHARED / "rviz-reference" / "zoo" / "zoo_prims.urdf"
    if zoo.exists():
        seed("urdf_loader", "zoo_prims.urdf", zoo.read_bytes())
    seed("urdf_loader", "every-joint.urdf", """<robot name="every">
  <material name="blue"><color rgba="0 0 0.8 1"/></material>
  <link name="base"><visual><geometry><box size="1 2 3"/></geometry><material name="blue"/></visual>
    <collision><origin xyz="0 0 1" rpy="0 1.57 0"/><geometry><sphere radius="0.5"/></geometry></collision></link>
  <link name="a"><visual><geometry><cylinder radius="0.1" length="2"/></geometry>
    <material name="red"><color rgba="1 0 0 0.5"/></material></visual></link>
  <link name="b"><visual><geometry><mesh filename="package://none/m.stl" scale="-1 1 1"/></geometry></visual></link>
  <link name="c"/><link name="d"/><link name="e"/><link name="f"/>
  <joint name="rev" type="revolute"><parent link="base"/><child link="a"/><axis xyz="0 0 1"/>
    <limit lower="0.5" upper="1" effort="1" velocity="1"/></joint>
  <joint name="pri" type="prismatic"><parent link="a"/><child link="b"/><origin xyz="1 0 0"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <joint name="con" type="continuous"><parent link="b"/><child link="c"/>
    <mimic joint="rev" multiplier="2" offset="0.1"/></joint>
  <joint name="fix" type="fixed"><parent link="c"/><child link="d"/></joint>
  <joint name="flo" type="floating"><parent link="d"/><child link="e"/></joint>
  <joint name="pla" type="planar"><parent link="e"/><child link="f"/><axis xyz="1 1 0"/></joint>
</robot>
""")


def joint_file_seeds():
    # the first byte picks the format: even YAML, odd JSON; bit 1 clamps
    files = {
        "map.yaml": (2, "shoulder: 0.5\nslide: 0.3\nspin: 1\n"),
        "state.yaml": (0, "name: [shoulder, slide]\nposition: [0.1, 9]\nvelocity: []\n"),
        "flow.yaml": (2, "{shoulder: -2, weld: 1, spin: .inf}\n"),
        "anchors.yaml": (0, "a: &x 0.5\nshoulder: *x\n"),
        "map.json": (3, '{"shoulder": 0.5, "slide": 1e-3}'),
        "state.json": (1, '{"name": ["shoulder", "spin"], "position": [0.2, null]}'),
        "nested.json": (1, '{"shoulder": [[1]], "slide": {"x": 1}}'),
    }
    for name, (flags, text) in files.items():
        seed("joint_file", name, bytes([flags]) + text.encode())


def rviz_seeds():
    seed("rviz_config", "mrm.rviz", (ROOT / "tests" / "data" / "mrm.rviz").read_bytes())
    for i, text in enumerate(raw_strings(ROOT / "tests" / "render" / "rviz_config_test.cpp")):
        seed("rviz_config", "test-%02d.rviz" % i, text)


def png(width, height, colour_type, bit_depth, rows, interlace=0, extra_chunks=()):
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(
            ">I", zlib.crc32(kind + body) & 0xFFFFFFFF)
    header = struct.pack(">IIBBBBB", width, height, bit_depth, colour_type, 0, 0, interlace)
    data = b"".join(b"\0" + row for row in rows)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) +
            b"".join(chunk(k, v) for k, v in extra_chunks) +
            chunk(b"IDAT", zlib.compress(data)) + chunk(b"IEND", b""))


def png_seeds():
    seed("png_reader", "rgb8.png", png(3, 2, 2, 8, [bytes(range(9)), bytes(range(100, 109))]))
    seed("png_reader", "grey1.png", png(9, 2, 0, 1, [b"\xa5\x80", b"\x5a\x00"]))
    seed("png_reader", "grey16.png", png(2, 2, 0, 16, [b"\x01\x02\x03\x04", b"\xff\xff\x00\x00"]))
    seed("png_reader", "rgba8.png", png(2, 1, 6, 8, [b"\x10\x20\x30\x40\x50\x60\x70\x80"]))
    seed("png_reader", "grey_alpha8.png", png(2, 1, 4, 8, [b"\x10\x20\x30\x40"]))
    seed("png_reader", "rgb16.png", png(1, 2, 2, 16, [bytes(6), b"\xff" * 6]))
    palette = [(b"PLTE", b"\xff\x00\x00\x00\xff\x00\x00\x00\xff"), (b"tRNS", b"\x80")]
    seed("png_reader", "palette4.png", png(3, 1, 3, 4, [b"\x01\x20"], extra_chunks=palette))
    seed("png_reader", "interlaced.png",
         png(3, 3, 0, 8, [b"\x01", b"\x02", b"\x03\x04", b"\x05", b"\x06", b"\x07\x08\x09"], 1))


if __name__ == "__main__":
    xacro_seeds()
    expression_seeds()
    urdf_seeds()
    joint_file_seeds()
    rviz_seeds()
    png_seeds()
