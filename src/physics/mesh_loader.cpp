#include "physics/mesh_loader.hpp"

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>

#include "physics/physics_error.hpp"

namespace mechsim::physics {
namespace {

std::string lower_extension(const std::string& path) {
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos) return {};
  std::string ext = path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

std::vector<char> read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw PhysicsError("mesh '" + path + "': cannot open the file");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

bool is_binary_stl(const std::vector<char>& bytes) {
  if (bytes.size() < 84) return false;
  std::uint32_t n = 0;
  std::memcpy(&n, bytes.data() + 80, 4);
  return bytes.size() == 84 + 50 * static_cast<std::size_t>(n) && n > 0;
}

void put_float(std::vector<char>& out, float v) {
  char b[4];
  std::memcpy(b, &v, 4);
  out.insert(out.end(), b, b + 4);
}

std::vector<char> scene_to_binary_stl(const aiScene& scene, const std::string& path) {
  std::uint32_t triangles = 0;
  for (unsigned m = 0; m < scene.mNumMeshes; ++m)
    for (unsigned f = 0; f < scene.mMeshes[m]->mNumFaces; ++f)
      if (scene.mMeshes[m]->mFaces[f].mNumIndices == 3) ++triangles;
  if (triangles == 0) throw PhysicsError("mesh '" + path + "': no triangles after import");
  std::vector<char> out(80, '\0');
  const char header[] = "mechsim: converted by assimp";
  std::memcpy(out.data(), header, sizeof(header) - 1);
  out.reserve(84 + 50 * static_cast<std::size_t>(triangles));
  char count[4];
  std::memcpy(count, &triangles, 4);
  out.insert(out.end(), count, count + 4);
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    const aiMesh& mesh = *scene.mMeshes[m];
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) continue;
      const aiVector3D& a = mesh.mVertices[face.mIndices[0]];
      const aiVector3D& b = mesh.mVertices[face.mIndices[1]];
      const aiVector3D& c = mesh.mVertices[face.mIndices[2]];
      aiVector3D n = (b - a) ^ (c - a);
      const float len = n.Length();
      if (len > 0.0f) n /= len;
      const aiVector3D* corners[4] = {&n, &a, &b, &c};
      for (const aiVector3D* v : corners) {
        put_float(out, v->x);
        put_float(out, v->y);
        put_float(out, v->z);
      }
      out.push_back('\0');
      out.push_back('\0');
    }
  }
  return out;
}

}  // namespace

MeshBytes load_mesh_for_mujoco(const std::string& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".stl" || ext == ".obj") {
    std::vector<char> bytes = read_file(path);
    if (ext == ".obj") return {".obj", std::move(bytes), false};
    if (is_binary_stl(bytes)) return {".stl", std::move(bytes), false};
  }
  Assimp::Importer importer;
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
  const aiScene* scene = importer.ReadFile(
      path, aiProcess_Triangulate | aiProcess_PreTransformVertices | aiProcess_SortByPType);
  if (scene == nullptr)
    throw PhysicsError("mesh '" + path + "': assimp could not read it: " + importer.GetErrorString());
  return {".stl", scene_to_binary_stl(*scene, path), true};
}

MeshBounds mesh_bounds(const std::string& path, const double scale[3]) {
  Assimp::Importer importer;
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
  const aiScene* scene = importer.ReadFile(path, aiProcess_Triangulate | aiProcess_PreTransformVertices);
  if (scene == nullptr)
    throw PhysicsError("mesh '" + path + "': assimp could not read it: " + importer.GetErrorString());
  MeshBounds b;
  bool any = false;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh& mesh = *scene->mMeshes[m];
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const double p[3] = {mesh.mVertices[v].x * scale[0], mesh.mVertices[v].y * scale[1], mesh.mVertices[v].z * scale[2]};
      for (int i = 0; i < 3; ++i) {
        b.min[i] = any ? std::min(b.min[i], p[i]) : p[i];
        b.max[i] = any ? std::max(b.max[i], p[i]) : p[i];
      }
      any = true;
    }
  }
  if (!any) throw PhysicsError("mesh '" + path + "': no vertices");
  return b;
}

}  // namespace mechsim::physics
