// LoadMeshFile against small generated files, one per RViz rule (mesh_loader.cpp and
// robot_link.cpp): faceted STL with rebuilt normals, COLLADA materials, unit and up axis, assimp's
// default material, OBJ/MTL colours with smooth normals, the cache and the errors; then the zoo's
// reference meshes when ../shared is present.
#include "geometry/mesh_file.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "common/error.h"
#include "mesh_test_files.h"

namespace urdfsnap::geometry {
namespace {

namespace fs = std::filesystem;

using Triangle = std::array<Eigen::Vector3f, 3>;

// The unit cube [0,1]^3 as 12 counter-clockwise triangles seen from outside.
std::vector<Triangle> Cube() {
  std::vector<Triangle> triangles;
  for (int axis = 0; axis < 3; ++axis) {
    for (const float side : {0.f, 1.f}) {
      const Eigen::Vector3f u = Eigen::Vector3f::Unit((axis + 1) % 3);
      const Eigen::Vector3f v = Eigen::Vector3f::Unit((axis + 2) % 3);
      const Eigen::Vector3f o = side * Eigen::Vector3f::Unit(axis);
      Triangle a{o, o + u, o + u + v}, b{o, o + u + v, o + v};
      if (side == 0) std::swap(a[1], a[2]), std::swap(b[1], b[2]);  // u x v = +axis: flip for -axis
      triangles.push_back(a);
      triangles.push_back(b);
    }
  }
  return triangles;
}

Eigen::Vector3f FaceNormal(const Triangle& t) {
  return (t[1] - t[0]).cross(t[2] - t[0]).normalized();
}

// Facet normals from the winding, times `normal_sign`.
std::string BinaryStl(const std::vector<Triangle>& triangles, float normal_sign = 1.f) {
  std::string out(80, ' ');
  const auto put = [&out](const void* data, size_t n) {
    out.append(static_cast<const char*>(data), n);
  };
  const auto count = static_cast<std::uint32_t>(triangles.size());
  put(&count, 4);
  for (const Triangle& t : triangles) {
    const Eigen::Vector3f n = normal_sign * FaceNormal(t);
    put(n.data(), 12);
    for (const Eigen::Vector3f& p : t) put(p.data(), 12);
    put("\0\0", 2);
  }
  return out;
}

// Every facet normal written as 0 0 0, as many CAD exporters do.
std::string AsciiStlZeroNormals(const std::vector<Triangle>& triangles) {
  std::string out = "solid part\n";
  for (const Triangle& t : triangles) {
    out += " facet normal 0 0 0\n  outer loop\n";
    for (const Eigen::Vector3f& p : t) {
      out += "   vertex " + std::to_string(p.x()) + " " + std::to_string(p.y()) + " " +
             std::to_string(p.z()) + "\n";
    }
    out += "  endloop\n endfacet\n";
  }
  return out + "endsolid part\n";
}

// A COLLADA document: `asset` inside <asset>, one lambert effect and material per entry of
// `colours` (ids m0, m1, ...), and one node per triangle list of `triangles` (material symbol
// "sym" bound to `materials[i]` when given), placed by `node_xml[i]` (translate/rotate elements).
struct DaeGeometry {
  std::vector<float> positions;
  std::vector<int> indices;
  std::string material;  // "" for none
  std::string node_xml;
};

std::string Dae(const std::string& asset, const std::vector<std::string>& colours,
                const std::vector<DaeGeometry>& geometries) {
  std::string effects, materials, geoms, nodes;
  for (size_t i = 0; i < colours.size(); ++i) {
    const std::string id = std::string("m").append(std::to_string(i));
    effects += std::string("<effect id=\"") + id +
               "-fx\"><profile_COMMON><technique sid=\"common\"><lambert><diffuse><color>" +
               colours[i] + "</color></diffuse></lambert></technique></profile_COMMON></effect>\n";
    materials += std::string("<material id=\"") + id + "\" name=\"" + id +
                 "\"><instance_effect url=\"#" + id + "-fx\"/></material>\n";
  }
  for (size_t i = 0; i < geometries.size(); ++i) {
    const DaeGeometry& g = geometries[i];
    const std::string id = std::string("g").append(std::to_string(i));
    std::string floats, ps;
    for (const float f : g.positions) floats += std::to_string(f) + " ";
    for (const int k : g.indices) ps += std::to_string(k) + " ";
    geoms += "<geometry id=\"" + id + "\"><mesh><source id=\"" + id + "-p\"><float_array id=\"" +
             id + "-a\" count=\"" + std::to_string(g.positions.size()) + "\">" + floats +
             "</float_array><technique_common><accessor source=\"#" + id + "-a\" count=\"" +
             std::to_string(g.positions.size() / 3) +
             "\" stride=\"3\"><param name=\"X\" type=\"float\"/><param name=\"Y\" "
             "type=\"float\"/><param name=\"Z\" "
             "type=\"float\"/></accessor></technique_common></source><vertices id=\"" +
             id + "-v\"><input semantic=\"POSITION\" source=\"#" + id +
             "-p\"/></vertices><triangles " + (g.material.empty() ? "" : "material=\"sym\" ") +
             "count=\"" + std::to_string(g.indices.size() / 3) +
             "\"><input semantic=\"VERTEX\" source=\"#" + id + "-v\" offset=\"0\"/><p>" + ps +
             "</p></triangles></mesh></geometry>\n";
    const std::string bind =
        g.material.empty()
            ? ""
            : "<bind_material><technique_common><instance_material symbol=\"sym\" target=\"#" +
                  g.material + "\"/></technique_common></bind_material>";
    nodes += "<node id=\"n" + std::to_string(i) + "\">" + g.node_xml +
             "<instance_geometry url=\"#" + id + "\">" + bind + "</instance_geometry></node>\n";
  }
  return "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
         "<COLLADA xmlns=\"http://www.collada.org/2005/11/COLLADASchema\" "
         "version=\"1.4.1\">\n<asset>" +
         asset + "</asset>\n<library_effects>" + effects +
         "</library_effects>\n<library_materials>" + materials +
         "</library_materials>\n<library_geometries>" + geoms +
         "</library_geometries>\n<library_visual_scenes><visual_scene id=\"s\">" + nodes +
         "</visual_scene></library_visual_scenes>\n<scene><instance_visual_scene "
         "url=\"#s\"/></scene>\n</COLLADA>\n";
}

// One counter-clockwise triangle in the file's XY plane, facing +Z.
const std::vector<float> kTrianglePositions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
const std::vector<int> kTriangleIndices = {0, 1, 2};

void ExpectWellFormed(const TriangleMesh& mesh) {
  ASSERT_EQ(mesh.positions.size(), mesh.normals.size());
  ASSERT_EQ(mesh.indices.size() % 3, 0u);
  for (const std::uint32_t index : mesh.indices) ASSERT_LT(index, mesh.positions.size());
  for (const Eigen::Vector3f& n : mesh.normals) EXPECT_NEAR(n.norm(), 1.0, 1e-5);
}

Triangle TriangleAt(const TriangleMesh& mesh, int t) {
  return {mesh.positions[mesh.indices[3 * t]], mesh.positions[mesh.indices[3 * t + 1]],
          mesh.positions[mesh.indices[3 * t + 2]]};
}

// Faceted: each corner's normal is its triangle's winding normal.
void ExpectFlatFromWinding(const TriangleMesh& mesh) {
  for (int t = 0; t < mesh.triangle_count(); ++t) {
    const Triangle tri = TriangleAt(mesh, t);
    for (int c = 0; c < 3; ++c) {
      EXPECT_TRUE(mesh.normals[mesh.indices[3 * t + c]].isApprox(FaceNormal(tri), 1e-5f))
          << "triangle " << t;
    }
  }
}

using MeshFileTest = MeshFilesTest;

TEST_F(MeshFileTest, StlTakesTheUrdfMaterialAndIsFaceted) {
  // binary with correct facet normals; ASCII with every normal 0 0 0, rebuilt from the winding;
  // an upper-case extension, which RViz lower-cases before comparing with ".stl"
  const std::vector<std::string> paths = {Write("cube.stl", BinaryStl(Cube())),
                                          Write("cube_ascii.STL", AsciiStlZeroNormals(Cube()))};
  for (const std::string& path : paths) {
    SCOPED_TRACE(path);
    const auto file = LoadMeshFile(path);
    EXPECT_EQ(file->triangle_count, 12u);
    ASSERT_EQ(file->parts.size(), 1u);
    EXPECT_TRUE(file->parts[0].takes_urdf_material);
    ExpectWellFormed(file->parts[0].mesh);
    ExpectFlatFromWinding(file->parts[0].mesh);
  }
}

TEST_F(MeshFileTest, StlFacetNormalsAreUsedAsGivenEvenWhenWrong) {
  // inward normals are valid data to assimp: RViz draws those faces black
  const auto file = LoadMeshFile(Write("inward.stl", BinaryStl(Cube(), -1.f)));
  const TriangleMesh& mesh = file->parts[0].mesh;
  for (int t = 0; t < mesh.triangle_count(); ++t) {
    const Triangle tri = TriangleAt(mesh, t);
    EXPECT_TRUE(mesh.normals[mesh.indices[3 * t]].isApprox(-FaceNormal(tri), 1e-5f))
        << "triangle " << t;
  }
}

TEST_F(MeshFileTest, DaeKeepsTheDiffuseOfEachMaterialAndAppliesNodeTransforms) {
  const std::string dae =
      Dae("<unit meter=\"1\"/><up_axis>Z_UP</up_axis>", {"0.1 0.2 0.9 1", "1 1 1 0.5"},
          {{kTrianglePositions, kTriangleIndices, "m0", ""},
           {kTrianglePositions, kTriangleIndices, "m1",
            "<translate>0 0 2</translate><rotate>0 0 1 90</rotate>"}});
  const auto file = LoadMeshFile(Write("two.dae", dae));
  EXPECT_EQ(file->triangle_count, 2u);
  ASSERT_EQ(file->parts.size(), 2u);
  std::vector<Eigen::Vector4f> diffuse;
  for (const MeshPart& part : file->parts) {
    EXPECT_FALSE(part.takes_urdf_material);
    ExpectWellFormed(part.mesh);
    ExpectFlatFromWinding(part.mesh);
    diffuse.push_back(part.diffuse);
  }
  EXPECT_TRUE(diffuse[0].isApprox(Eigen::Vector4f(0.1f, 0.2f, 0.9f, 1.f)));
  // the alpha of the colour is not used: RViz's mesh materials are opaque
  EXPECT_TRUE(diffuse[1].isApprox(Eigen::Vector4f(1.f, 1.f, 1.f, 1.f)));
  // the second node: turned 90 degrees about z, then raised 2 m; file vertex (1,0,0) -> (0,1,2)
  const TriangleMesh& moved = file->parts[1].mesh;
  EXPECT_TRUE(moved.positions[moved.indices[1]].isApprox(Eigen::Vector3f(0, 1, 2), 1e-5f));
  EXPECT_TRUE(moved.normals[0].isApprox(Eigen::Vector3f(0, 0, 1), 1e-5f));
}

TEST_F(MeshFileTest, DaeUnitIsHonouredAndTheUpAxisRotationDropped) {
  // an L authored in millimetres in a Y_UP file: the bar's tip at y = 300 mm stays on +y
  const std::vector<float> positions = {0, 0, 0, 20, 0, 0, 0, 300, 0};
  const std::string dae =
      Dae("<unit name=\"millimeter\" meter=\"0.001\"/><up_axis>Y_UP</up_axis>", {"1 0.5 0 1"},
          {{positions, kTriangleIndices, "m0", "<translate>0 0 10</translate>"}});
  const auto file = LoadMeshFile(Write("bracket_mm_yup.dae", dae));
  ASSERT_EQ(file->parts.size(), 1u);
  const TriangleMesh& mesh = file->parts[0].mesh;
  EXPECT_TRUE(mesh.positions[mesh.indices[2]].isApprox(Eigen::Vector3f(0, 0.3f, 0.01f), 1e-5f));
  EXPECT_TRUE(mesh.normals[0].isApprox(Eigen::Vector3f(0, 0, 1), 1e-5f));
  EXPECT_TRUE(file->parts[0].diffuse.isApprox(Eigen::Vector4f(1, 0.5f, 0, 1)));
}

TEST_F(MeshFileTest, DaeZUpIsUsedAsAuthored) {
  const std::string dae =
      Dae("<up_axis>Z_UP</up_axis>", {}, {{kTrianglePositions, kTriangleIndices, "", ""}});
  const auto file = LoadMeshFile(Write("z_up.dae", dae));
  ASSERT_EQ(file->parts.size(), 1u);
  const TriangleMesh& mesh = file->parts[0].mesh;
  EXPECT_TRUE(mesh.positions[mesh.indices[2]].isApprox(Eigen::Vector3f(0, 1, 0), 1e-5f));
}

TEST_F(MeshFileTest, DaeWithoutMaterialsKeepsAssimpsDefaultGrey) {
  const std::string dae = Dae("", {}, {{kTrianglePositions, kTriangleIndices, "", ""}});
  const auto file = LoadMeshFile(Write("plain.dae", dae));
  ASSERT_EQ(file->parts.size(), 1u);
  EXPECT_FALSE(file->parts[0].takes_urdf_material);
  EXPECT_TRUE(file->parts[0].diffuse.isApprox(Eigen::Vector4f(0.6f, 0.6f, 0.6f, 1.f)));
}

TEST_F(MeshFileTest, ObjKeepsMtlColoursAndItsSmoothNormals) {
  Write("parts.mtl",
        "newmtl violet\nKd 0.5 0.2 0.8\nd 1\nnewmtl glow\nKd 1 1 1\nKe 0.25 0 0\nd 0.25\n");
  // a quad with normals tilted outward at its corners (smooth, not the face's +z), and a triangle
  const std::string obj =
      "mtllib parts.mtl\n"
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\n"
      "vn -0.6 -0.6 0.52915\nvn 0.6 -0.6 0.52915\nvn 0.6 0.6 0.52915\nvn -0.6 0.6 0.52915\nvn 0 0 "
      "1\n"
      "o body\nusemtl violet\nf 1//1 2//2 3//3 4//4\n"
      "o cover\nusemtl glow\nf 5//5 6//5 7//5\n";
  const auto file = LoadMeshFile(Write("knob.obj", obj));
  EXPECT_EQ(file->triangle_count, 3u);
  ASSERT_EQ(file->parts.size(), 2u);
  const MeshPart* body = nullptr;
  const MeshPart* cover = nullptr;
  for (const MeshPart& part : file->parts) (part.mesh.triangle_count() == 2 ? body : cover) = &part;
  ASSERT_TRUE(body && cover);
  EXPECT_FALSE(body->takes_urdf_material);
  EXPECT_TRUE(body->diffuse.isApprox(Eigen::Vector4f(0.5f, 0.2f, 0.8f, 1.f)));
  // RViz ignores the opacity (d) and keeps the emission (Ke) as self-illumination
  EXPECT_TRUE(cover->diffuse.isApprox(Eigen::Vector4f(1, 1, 1, 1))) << cover->diffuse.transpose();
  EXPECT_TRUE(cover->emissive.isApprox(Eigen::Vector3f(0.25f, 0, 0)))
      << cover->emissive.transpose();
  EXPECT_TRUE(body->emissive.isZero());
  ExpectWellFormed(body->mesh);
  for (size_t v = 0; v < body->mesh.positions.size(); ++v) {
    const Eigen::Vector3f& p = body->mesh.positions[v];
    const Eigen::Vector3f expected =
        Eigen::Vector3f(p.x() > 0.5f ? 0.6f : -0.6f, p.y() > 0.5f ? 0.6f : -0.6f, 0.52915f)
            .normalized();
    EXPECT_TRUE(body->mesh.normals[v].isApprox(expected, 1e-4f)) << "vertex " << v;
  }
}

TEST_F(MeshFileTest, ObjTextureMapIsFoundBesideTheMeshAndItsCoordinatesKept) {
  Write("maps/m.mtl", "newmtl skin\nKd 0.5 0.5 1\nmap_Kd ../images/skin.png\nnewmtl plain\nKd 1 0 0\n");
  const std::string obj =
      "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
      "o skin\nusemtl skin\nf 1/1 2/2 3/3\no plain\nusemtl plain\nf 1 3 2\n";
  const auto file = LoadMeshFile(Write("maps/t.obj", obj));
  ASSERT_EQ(file->parts.size(), 2u);
  const MeshPart& skin = file->parts[0].texture.empty() ? file->parts[1] : file->parts[0];
  const MeshPart& plain = &skin == &file->parts[0] ? file->parts[1] : file->parts[0];
  // mesh_loader.cpp: "Assume textures are in paths relative to the mesh"; the colour still tints
  EXPECT_EQ(fs::path(skin.texture).lexically_normal(), (dir_ / "images/skin.png").lexically_normal());
  EXPECT_TRUE(skin.diffuse.isApprox(Eigen::Vector4f(0.5f, 0.5f, 1, 1)));
  EXPECT_TRUE(plain.texture.empty());
  // aiProcess_FlipUVs: v = 1 - the file's v, so v = 0 is the image's top row
  ASSERT_EQ(skin.mesh.uvs.size(), skin.mesh.positions.size());
  for (size_t v = 0; v < skin.mesh.positions.size(); ++v) {
    const Eigen::Vector3f& p = skin.mesh.positions[v];
    EXPECT_TRUE(skin.mesh.uvs[v].isApprox(Eigen::Vector2f(p.x(), 1 - p.y()))) << "vertex " << v;
  }
}

// tests/data/texture_maps_description: one material per file with the maps its name lists
TEST_F(MeshFileTest, EveryTextureMapIsATextureUnitShowingTheDiffuseMap) {
  const fs::path meshes = fs::path(URDFSNAP_SOURCE_DIR) / "tests/data/texture_maps_description/meshes";
  struct Case {
    const char* file;
    int units;
    const char* texture;   // file name of the image the units show, "" for none
  };
  const Case cases[] = {
      {"plain.dae", 0, ""},
      {"diffuse.dae", 1, "diffuse.png"},
      {"diffuse_bump.dae", 2, "diffuse.png"},                 // COLLADA bump: assimp's normals map
      {"diffuse_specular_bump.dae", 3, "diffuse.png"},
      {"diffuse_emission.dae", 2, "diffuse.png"},
      {"diffuse_reflective_transparent.dae", 3, "diffuse.png"},
      {"diffuse_bump.obj", 2, "diffuse.png"},                 // OBJ bump: assimp's height map
      {"bump_only.dae", 1, ""},                               // a unit, but no diffuse map for it
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.file);
    const auto file = LoadMeshFile((meshes / c.file).string());
    const MeshPart& part = file->parts.back();   // the OBJ's first material is assimp's default
    EXPECT_FALSE(part.takes_urdf_material);
    EXPECT_EQ(part.texture_units, c.units);
    // joined as mesh_loader.cpp joins them: the mesh's folder, "/", the name in the file
    EXPECT_EQ(part.texture, *c.texture ? meshes.string() + "/" + c.texture : "");
  }
  // a map of any kind without a diffuse one: the colour stays, the unit has no image
  const auto bump_only = LoadMeshFile((meshes / "bump_only.dae").string());
  EXPECT_TRUE(bump_only->parts[0].diffuse.isApprox(Eigen::Vector4f(0.8f, 0.6f, 0.4f, 1)));
}

// A glTF file of one triangle (0,0,0), (1,0,0), (0,1,0), facing +z, placed by `nodes` (a JSON
// array whose first node is the scene's only root, one of them holding mesh 0) and with
// `material` (a JSON object, which may close the array and add more top-level entries).
std::string GltfTriangle(const std::string& nodes, const std::string& material) {
  const std::string triangle =   // 3 float positions, then indices 0 1 2 as uint16 (+ padding)
      "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIAAAA=";
  return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": )" + nodes +
         R"(, "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]}],
    "materials": [)" + material + R"(],
    "buffers": [{"byteLength": 44, "uri": "data:application/octet-stream;base64,)" + triangle + R"("}],
    "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                    {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                   "min": [0, 0, 0], "max": [1, 1, 0]},
                  {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}]})";
}

TEST_F(MeshFileTest, AnEmbeddedDiffuseMapIsNoImageForTheTextureUnits) {
  // the base colour texture is a PNG inside the file: assimp names it "*0" and reports it as a
  // diffuse and a base colour map; RViz looks for a file named "*0"
  const std::string png_1x1 =
      "iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAIAAACQd1PeAAAADElEQVR4nGP4z8AAAAMBAQDJ/pLvAAAAAElFTkSuQmCC";
  const std::string gltf = GltfTriangle(R"([{"mesh": 0}])",
                                        R"({"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
    "textures": [{"source": 0}], "images": [{"uri": "data:image/png;base64,)" + png_1x1 + R"("})");
  const auto file = LoadMeshFile(Write("embedded.gltf", gltf));
  ASSERT_EQ(file->parts.size(), 1u);
  EXPECT_EQ(file->parts[0].texture_units, 2);
  EXPECT_EQ(file->parts[0].texture, "");
}

TEST_F(MeshFileTest, TheRootNodeKeepsItsScaleAndTranslationButNotItsRotation) {
  // root: turned 90 degrees about x, halved, moved 1 m along z; its child turned 90 degrees about z
  const std::string nodes = R"([
      {"children": [1], "rotation": [0.7071068, 0, 0, 0.7071068], "scale": [0.5, 0.5, 0.5],
       "translation": [0, 0, 1]},
      {"mesh": 0, "rotation": [0, 0, 0.7071068, 0.7071068]}])";
  const auto nested = LoadMeshFile(Write("nested.gltf", GltfTriangle(nodes, "{}")));
  ASSERT_EQ(nested->parts.size(), 1u);
  // (1,0,0) -> child (0,1,0) -> root without rotation: (0, 0.5, 1); the face turns to +z still
  const TriangleMesh& mesh = nested->parts[0].mesh;
  EXPECT_TRUE(mesh.positions[1].isApprox(Eigen::Vector3f(0, 0.5f, 1), 1e-5f)) << mesh.positions[1].transpose();
  EXPECT_TRUE(mesh.positions[2].isApprox(Eigen::Vector3f(-0.5f, 0, 1), 1e-5f)) << mesh.positions[2].transpose();
  EXPECT_TRUE(mesh.normals[0].isApprox(Eigen::Vector3f(0, 0, 1), 1e-5f)) << mesh.normals[0].transpose();
  // the mesh on the root itself: the same rule
  const auto on_root = LoadMeshFile(Write("root.gltf", GltfTriangle(
      R"([{"mesh": 0, "rotation": [0.7071068, 0, 0, 0.7071068], "translation": [0, 0, 1]}])", "{}")));
  EXPECT_TRUE(on_root->parts[0].mesh.positions[2].isApprox(Eigen::Vector3f(0, 1, 1), 1e-5f))
      << on_root->parts[0].mesh.positions[2].transpose();
}

TEST_F(MeshFileTest, AnAbsoluteTextureNameStaysInsideTheMeshFolder) {
  // mesh_loader.cpp appends the name to the folder and a "/": "/skin.png" is the folder's file
  Write("m.mtl", "newmtl s\nKd 1 1 1\nmap_Kd /skin.png\n");
  const auto file = LoadMeshFile(Write("t.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl s\nf 1 2 3\n"));
  EXPECT_EQ(file->parts.back().texture, dir_.string() + "//skin.png");
}

TEST_F(MeshFileTest, EachFileIsLoadedOnce) {
  const std::string path = Write("cube.stl", BinaryStl(Cube()));
  const auto first = LoadMeshFile(path);
  EXPECT_EQ(LoadMeshFile(path), first);
  EXPECT_EQ(LoadMeshFile((dir_ / "." / "cube.stl").string()), first);
  Write("other.stl", BinaryStl(Cube()));
  EXPECT_NE(LoadMeshFile((dir_ / "other.stl").string()), first);
}

TEST_F(MeshFileTest, ConcurrentCallersShareOneLoad) {
  const std::string path = Write("shared.stl", BinaryStl(Cube()));
  std::vector<std::shared_ptr<const MeshFile>> loaded(4);
  std::vector<std::thread> threads;
  for (auto& slot : loaded) threads.emplace_back([&slot, &path] { slot = LoadMeshFile(path); });
  for (std::thread& thread : threads) thread.join();
  for (const auto& file : loaded) EXPECT_EQ(file, loaded[0]);
}

void ExpectErrorNaming(const std::string& path, const std::string& what) {
  try {
    LoadMeshFile(path);
    FAIL() << "no error for " << path;
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(std::filesystem::path(path).filename().string()),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
  }
}

TEST_F(MeshFileTest, ErrorsNameTheFile) {
  ExpectErrorNaming((dir_ / "missing.stl").string(), "cannot read mesh file");
  ExpectErrorNaming(Write("garbage.dae", std::string("\x01\x02garbage\xff not a mesh", 20)),
                    "cannot read mesh file");
  ExpectErrorNaming(Write("empty.stl", ""), "cannot read mesh file");
  // a file that failed is not cached: once fixed it loads
  const std::string fixed = Write("empty.stl", BinaryStl(Cube()));
  EXPECT_EQ(LoadMeshFile(fixed)->triangle_count, 12u);
}

// The meshes of the zoo reference robot, as the table of zoo/README.md describes them.
TEST(ZooMeshes, LoadAsTheReferenceImagesShow) {
  const std::filesystem::path meshes = std::filesystem::path(URDFSNAP_SOURCE_DIR) /
                                       "../shared/rviz-reference/zoo/zoo_mesh_description/meshes";
  if (!std::filesystem::is_directory(meshes)) GTEST_SKIP() << meshes << " is not there";
  const auto torus = LoadMeshFile((meshes / "torus.stl").string());
  EXPECT_EQ(torus->triangle_count, 864u);
  EXPECT_TRUE(torus->parts[0].takes_urdf_material);

  const auto gear = LoadMeshFile((meshes / "gear_ascii.stl").string());
  EXPECT_EQ(gear->triangle_count, 240u);
  for (const MeshPart& part : gear->parts) ExpectFlatFromWinding(part.mesh);

  const auto two_tone = LoadMeshFile((meshes / "two_tone.dae").string());
  ASSERT_EQ(two_tone->parts.size(), 2u);
  for (const MeshPart& part : two_tone->parts) EXPECT_FALSE(part.takes_urdf_material);
  EXPECT_NE(two_tone->parts[0].diffuse, two_tone->parts[1].diffuse);

  // 0.3 m long along the file's +y, not stood up along +z
  const auto bracket = LoadMeshFile((meshes / "bracket_mm_yup.dae").string());
  Eigen::AlignedBox3f box;
  for (const MeshPart& part : bracket->parts) {
    for (const Eigen::Vector3f& p : part.mesh.positions) box.extend(p);
  }
  EXPECT_NEAR(box.sizes().y(), 0.3f, 1e-4f);
  EXPECT_LT(box.sizes().z(), 0.1f);

  const auto plain = LoadMeshFile((meshes / "plain_nomat.dae").string());
  for (const MeshPart& part : plain->parts)
    EXPECT_TRUE(part.diffuse.isApprox(Eigen::Vector4f(0.6f, 0.6f, 0.6f, 1.f)));

  const auto knob = LoadMeshFile((meshes / "knob.obj").string());
  EXPECT_GE(knob->parts.size(), 2u);
  for (const MeshPart& part : knob->parts) EXPECT_FALSE(part.takes_urdf_material);
}

}  // namespace
}  // namespace urdfsnap::geometry
