#!/usr/bin/env python3
"""Writes the meshbot sample robot: models/meshbot_description/ with package.xml, urdf/meshbot.urdf
and meshes/ in every mesh format urdfsnap reads (binary STL, ASCII STL, COLLADA, OBJ + MTL).

Standard library only and deterministic: the same files every run. The shapes are made here
(lathed and extruded profiles, a torus, a sphere); nothing is downloaded.
Usage: scripts/make_sample_meshes.py [OUTPUT_DIR]   (default: models/meshbot_description)
"""
import math
import os
import struct
import sys


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def normalized(v):
    n = math.sqrt(v[0] ** 2 + v[1] ** 2 + v[2] ** 2)
    return (v[0] / n, v[1] / n, v[2] / n)


def face_normal(t):
    return normalized(cross(sub(t[1], t[0]), sub(t[2], t[0])))


def num(x):
    """Fixed, short text for a float (no '-0')."""
    s = "%.6g" % x
    return "0" if s == "-0" else s


def lathe(profile, segments):
    """Triangles (counter-clockwise from outside) of `profile`, a list of (r, z) from the bottom
    centre up to the top centre, turned about z in `segments` steps; zero-area ones are dropped."""
    triangles = []
    for i in range(len(profile) - 1):
        (r0, z0), (r1, z1) = profile[i], profile[i + 1]
        for s in range(segments):
            a0, a1 = 2 * math.pi * s / segments, 2 * math.pi * (s + 1) / segments
            p = lambda r, z, a: (r * math.cos(a), r * math.sin(a), z)
            quad = (p(r0, z0, a0), p(r0, z0, a1), p(r1, z1, a1), p(r1, z1, a0))
            for t in ((quad[0], quad[1], quad[2]), (quad[0], quad[2], quad[3])):
                if len({t[0], t[1], t[2]}) == 3:
                    triangles.append(t)
    return triangles


def extrude(outline, z0, z1):
    """Triangles of the prism over the star-shaped (seen from its centre) counter-clockwise
    `outline` of (x, y) points, from z0 to z1, with fan caps around the centre."""
    triangles = []
    n = len(outline)
    for i in range(n):
        (x0, y0), (x1, y1) = outline[i], outline[(i + 1) % n]
        a, b, c, d = (x0, y0, z0), (x1, y1, z0), (x1, y1, z1), (x0, y0, z1)
        triangles += [(a, b, c), (a, c, d)]
        triangles.append(((0.0, 0.0, z1), d, c))  # top, seen from +z
        triangles.append(((0.0, 0.0, z0), b, a))  # bottom, seen from -z
    return triangles


def box(hx, hy, hz):
    """The box [-hx, hx] x [-hy, hy] x [-hz, hz] as 12 triangles."""
    triangles = []
    for axis in range(3):
        for sign in (1, -1):
            def corner(su, sv):
                p = [0.0, 0.0, 0.0]
                p[axis] = sign
                p[(axis + 1) % 3] = sign * su
                p[(axis + 2) % 3] = sv
                return (p[0] * hx, p[1] * hy, p[2] * hz)
            q = (corner(-1, -1), corner(1, -1), corner(1, 1), corner(-1, 1))
            triangles += [(q[0], q[1], q[2]), (q[0], q[2], q[3])]
    return triangles


def surface(point, normal, nu, nv):
    """An indexed grid over (u, v) in [0, 1]^2 with smooth normals; vertices that coincide (seams,
    poles) are shared; returns (vertices, normals, triangles of indices)."""
    vertices, normals, index, grid = [], [], {}, []
    for j in range(nv + 1):
        row = []
        for i in range(nu + 1):
            p = tuple(round(c, 9) + 0.0 for c in point(i / nu, j / nv))
            n = tuple(round(c, 9) + 0.0 for c in normal(i / nu, j / nv))
            if (p, n) not in index:
                index[(p, n)] = len(vertices)
                vertices.append(p)
                normals.append(n)
            row.append(index[(p, n)])
        grid.append(row)
    triangles = []
    for j in range(nv):
        for i in range(nu):
            a, b, c, d = grid[j][i], grid[j][i + 1], grid[j + 1][i + 1], grid[j + 1][i]
            for t in ((a, b, c), (a, c, d)):
                if len(set(t)) == 3:
                    triangles.append(t)
    return vertices, normals, triangles


def binary_stl(triangles, title):
    out = bytearray(title.encode().ljust(80, b" ")[:80])
    out += struct.pack("<I", len(triangles))
    for t in triangles:
        out += struct.pack("<12fH", *face_normal(t), *t[0], *t[1], *t[2], 0)
    return bytes(out)


def ascii_stl_zero_normals(triangles, name):
    """Every facet normal 0 0 0, as many CAD exporters write them; readers rebuild them."""
    lines = ["solid " + name]
    for t in triangles:
        lines += ["  facet normal 0 0 0", "    outer loop"]
        lines += ["      vertex %s %s %s" % tuple(num(c) for c in p) for p in t]
        lines += ["    endloop", "  endfacet"]
    lines.append("endsolid " + name)
    return "\n".join(lines) + "\n"


def collada(unit_name, unit_meter, materials, nodes):
    """A COLLADA 1.4.1 document, Z_UP. materials: [(id, (r, g, b))]; nodes: [(id, transform XML,
    triangles, material id)]; positions only, so readers build flat normals from the winding."""
    effects = "".join(
        '    <effect id="%s-fx"><profile_COMMON><technique sid="common"><phong>'
        "<emission><color>0 0 0 1</color></emission>"
        "<diffuse><color>%s 1</color></diffuse>"
        "<specular><color>0.5 0.5 0.5 1</color></specular><shininess><float>40</float></shininess>"
        "</phong></technique></profile_COMMON></effect>\n" % (mid, " ".join(num(c) for c in rgb))
        for mid, rgb in materials)
    library_materials = "".join(
        '    <material id="%s" name="%s"><instance_effect url="#%s-fx"/></material>\n' % (mid, mid, mid)
        for mid, _ in materials)
    geometries, scene = "", ""
    for nid, transform, triangles, material in nodes:
        points, index = [], {}
        indices = []
        for t in triangles:
            for p in t:
                if p not in index:
                    index[p] = len(points)
                    points.append(p)
                indices.append(index[p])
        floats = " ".join(num(c) for p in points for c in p)
        geometries += (
            '    <geometry id="%s-mesh" name="%s"><mesh>\n'
            '      <source id="%s-pos"><float_array id="%s-pos-array" count="%d">%s</float_array>\n'
            '        <technique_common><accessor source="#%s-pos-array" count="%d" stride="3">'
            '<param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>'
            "</accessor></technique_common></source>\n"
            '      <vertices id="%s-vtx"><input semantic="POSITION" source="#%s-pos"/></vertices>\n'
            '      <triangles material="%s-sym" count="%d"><input semantic="VERTEX" source="#%s-vtx" offset="0"/>'
            "<p>%s</p></triangles>\n"
            "    </mesh></geometry>\n" % (
                nid, nid, nid, nid, 3 * len(points), floats, nid, len(points), nid, nid, material,
                len(triangles), nid, " ".join(str(i) for i in indices)))
        scene += (
            '      <node id="%s" name="%s">%s<instance_geometry url="#%s-mesh"><bind_material><technique_common>'
            '<instance_material symbol="%s-sym" target="#%s"/></technique_common></bind_material>'
            "</instance_geometry></node>\n" % (nid, nid, transform, nid, material, material))
    return (
        '<?xml version="1.0" encoding="utf-8"?>\n'
        '<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">\n'
        "  <asset><contributor><authoring_tool>scripts/make_sample_meshes.py</authoring_tool></contributor>"
        '<unit name="%s" meter="%s"/><up_axis>Z_UP</up_axis></asset>\n'
        "  <library_effects>\n%s  </library_effects>\n"
        "  <library_materials>\n%s  </library_materials>\n"
        "  <library_geometries>\n%s  </library_geometries>\n"
        '  <library_visual_scenes><visual_scene id="scene" name="scene">\n%s'
        "  </visual_scene></library_visual_scenes>\n"
        '  <scene><instance_visual_scene url="#scene"/></scene>\n'
        "</COLLADA>\n" % (unit_name, unit_meter, effects, library_materials, geometries, scene))


def obj_parts(mtl_name, parts):
    """An OBJ with smooth vertex normals; parts: [(name, material, (vertices, normals, triangles))]."""
    lines = ["# meshbot handle, written by scripts/make_sample_meshes.py", "mtllib " + mtl_name]
    offset = 0
    for name, material, (vertices, normals, triangles) in parts:
        lines.append("o " + name)
        lines += ["v %s %s %s" % tuple(num(c) for c in p) for p in vertices]
        lines += ["vn %s %s %s" % tuple(num(c) for c in n) for n in normals]
        lines.append("usemtl " + material)
        lines += ["f " + " ".join("%d//%d" % (offset + i + 1, offset + i + 1) for i in t) for t in triangles]
        offset += len(vertices)
    return "\n".join(lines) + "\n"


def base_plate():
    """A bevelled octagonal plate with a raised hub, 0.5 m across (metres)."""
    profile = [(0.0, 0.0), (0.22, 0.0), (0.25, 0.02), (0.25, 0.05), (0.22, 0.07), (0.12, 0.07),
               (0.1, 0.09), (0.0, 0.09)]
    return lathe(profile, 8)


def star_column():
    """A five-pointed star prism, 300 mm tall (millimetres)."""
    outline = []
    for k in range(10):
        r = 45.0 if k % 2 == 0 else 20.0
        a = math.pi / 2 + k * math.pi / 5
        outline.append((r * math.cos(a), r * math.sin(a)))
    return extrude(outline, 0.0, 300.0)


def sensor_head():
    """An orange body and a dark lens looking along +x (centimetres)."""
    body = [tuple((x, y, z + 5.0) for x, y, z in t) for t in box(8.0, 6.0, 5.0)]
    lens = lathe([(0.0, 0.0), (3.5, 0.0), (3.5, 1.5), (2.8, 2.5), (0.0, 2.5)], 24)
    return collada("centimeter", "0.01", [("orange", (0.95, 0.45, 0.1)), ("lens_glass", (0.12, 0.14, 0.3))], [
        ("body", "", body, "orange"),
        # the lens is lathed along z: turned onto +x and moved to the body's front face
        ("lens", "<translate>8 0 5.5</translate><rotate>0 1 0 90</rotate>", lens, "lens_glass"),
    ])


def handle():
    """A green ring (torus) with a white ball on top (metres)."""
    R, r = 0.06, 0.015

    def torus_point(u, v):
        a, b = 2 * math.pi * u, 2 * math.pi * v
        return ((R + r * math.cos(b)) * math.cos(a), (R + r * math.cos(b)) * math.sin(a), r * math.sin(b))

    def torus_normal(u, v):
        a, b = 2 * math.pi * u, 2 * math.pi * v
        return (math.cos(b) * math.cos(a), math.cos(b) * math.sin(a), math.sin(b))

    # the ring stands in the xz plane: swap y and z (and flip one to keep the winding)
    ring = surface(lambda u, v: (lambda p: (p[0], -p[2], p[1]))(torus_point(u, v)),
                   lambda u, v: (lambda n: (n[0], -n[2], n[1]))(torus_normal(u, v)), 32, 12)
    rb, top = 0.02, R + r + 0.012

    def ball_normal(u, v):
        a, b = 2 * math.pi * u, math.pi * (v - 0.5)
        return (math.cos(b) * math.cos(a), math.cos(b) * math.sin(a), math.sin(b))

    ball = surface(lambda u, v: tuple(rb * c + o for c, o in zip(ball_normal(u, v), (0.0, 0.0, top))),
                   ball_normal, 20, 10)
    mtl = ("# meshbot handle materials, written by scripts/make_sample_meshes.py\n"
           "newmtl ring_green\nKa 0 0 0\nKd 0.2 0.7 0.3\nKs 0.2 0.2 0.2\nNs 20\nd 1\nillum 2\n\n"
           "newmtl ball_white\nKa 0 0 0\nKd 0.92 0.92 0.9\nKs 0 0 0\nd 1\nillum 1\n")
    return obj_parts("handle.mtl", [("ring", "ring_green", ring), ("ball", "ball_white", ball)]), mtl


PACKAGE_XML = """<?xml version="1.0"?>
<package format="2">
  <name>meshbot_description</name>
  <version>0.1.0</version>
  <description>urdfsnap's sample robot made of mesh files of every format it reads (generated by
    scripts/make_sample_meshes.py).</description>
  <maintainer email="urdfsnap@example.com">urdfsnap</maintainer>
  <license>BSD</license>
  <buildtool_depend>catkin</buildtool_depend>
</package>
"""

URDF = """<?xml version="1.0"?>
<!-- urdfsnap's mesh sample robot, generated by scripts/make_sample_meshes.py: every mesh format
     through package:// URIs. What each link shows, as RViz draws it:
       base_link  binary STL with facet normals, takes the URDF colour 'slate'
       column     ASCII STL with zero normals (rebuilt flat), authored in mm: scale 0.001; no
                  material, so red
       head       COLLADA in centimetres with two materials that win over the URDF colour
       handle     OBJ + MTL with smooth normals, scale 1.2 -->
<robot name="meshbot">
  <material name="slate">
    <color rgba="0.35 0.42 0.5 1"/>
  </material>

  <link name="base_link">
    <visual>
      <geometry>
        <mesh filename="package://meshbot_description/meshes/base_plate.stl"/>
      </geometry>
      <material name="slate"/>
    </visual>
  </link>

  <joint name="column_yaw" type="continuous">
    <parent link="base_link"/>
    <child link="column"/>
    <origin xyz="0 0 0.09" rpy="0 0 0"/>
    <axis xyz="0 0 1"/>
  </joint>

  <link name="column">
    <visual>
      <geometry>
        <mesh filename="package://meshbot_description/meshes/star_column.stl" scale="0.001 0.001 0.001"/>
      </geometry>
    </visual>
  </link>

  <joint name="head_tilt" type="revolute">
    <parent link="column"/>
    <child link="head"/>
    <origin xyz="0 0 0.3" rpy="0 0 0"/>
    <axis xyz="0 1 0"/>
    <limit lower="-0.8" upper="0.8" effort="10" velocity="1"/>
  </joint>

  <link name="head">
    <visual>
      <geometry>
        <mesh filename="package://meshbot_description/meshes/sensor_head.dae"/>
      </geometry>
      <material name="ignored_green">
        <color rgba="0 1 0 1"/>
      </material>
    </visual>
  </link>

  <joint name="handle_mount" type="fixed">
    <parent link="head"/>
    <child link="handle"/>
    <origin xyz="-0.02 0 0.19" rpy="0 0 0"/>
  </joint>

  <link name="handle">
    <visual>
      <geometry>
        <mesh filename="package://meshbot_description/meshes/handle.obj" scale="1.2 1.2 1.2"/>
      </geometry>
    </visual>
  </link>
</robot>
"""


def write(path, data):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "models", "meshbot_description")
    meshes = os.path.join(out, "meshes")
    write(os.path.join(meshes, "base_plate.stl"), binary_stl(base_plate(), "meshbot base plate (binary STL)"))
    write(os.path.join(meshes, "star_column.stl"), ascii_stl_zero_normals(star_column(), "star_column"))
    write(os.path.join(meshes, "sensor_head.dae"), sensor_head())
    obj, mtl = handle()
    write(os.path.join(meshes, "handle.obj"), obj)
    write(os.path.join(meshes, "handle.mtl"), mtl)
    write(os.path.join(out, "package.xml"), PACKAGE_XML)
    write(os.path.join(out, "urdf", "meshbot.urdf"), URDF)


if __name__ == "__main__":
    main()
