#include "geometry/mesh_export.h"

#include <assimp/scene.h>

#include <algorithm>
#include <assimp/Exporter.hpp>
#include <assimp/IOStream.hpp>
#include <assimp/IOSystem.hpp>
#include <cassert>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>
#include <stdexcept>

#include <sys/stat.h>
#include <unistd.h>

namespace railjoint {

namespace {

// Where assimp has several writers for one extension, the compact one.
const std::map<std::string, std::string> kPreferredFormat = {
    {"obj", "obj"}, {"ply", "plyb"}, {"stl", "stlb"}, {"glb", "glb2"}, {"gltf", "gltf2"}};

std::string lower_extension(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  if (!extension.empty()) extension.erase(0, 1);
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

// Assimp's own file streams ignore a failed write: a full disk gave a
// truncated mesh and success. These note the first failure of any file the
// export writes (short fwrite, fflush or fclose), and export_meshes throws it.
class CheckedStream : public Assimp::IOStream {
 public:
  CheckedStream(std::FILE* file, std::string path, std::string& failure)
      : file_(file), path_(std::move(path)), failure_(failure) {}
  ~CheckedStream() override {
    if (std::fclose(file_) != 0) note();
  }
  size_t Read(void* buffer, size_t size, size_t count) override { return std::fread(buffer, size, count, file_); }
  size_t Write(const void* buffer, size_t size, size_t count) override {
    const size_t written = std::fwrite(buffer, size, count, file_);
    if (written != count) note();
    return written;
  }
  aiReturn Seek(size_t offset, aiOrigin origin) override {
    const int whence = origin == aiOrigin_SET ? SEEK_SET : origin == aiOrigin_CUR ? SEEK_CUR : SEEK_END;
    return std::fseek(file_, static_cast<long>(offset), whence) == 0 ? aiReturn_SUCCESS : aiReturn_FAILURE;
  }
  size_t Tell() const override { return static_cast<size_t>(std::ftell(file_)); }
  size_t FileSize() const override {
    struct stat info {};
    return fstat(fileno(file_), &info) == 0 ? static_cast<size_t>(info.st_size) : 0;
  }
  void Flush() override {
    if (std::fflush(file_) != 0) note();
  }

 private:
  void note() {
    if (failure_.empty()) failure_ = path_ + ": " + std::strerror(errno);
  }
  std::FILE* file_;
  std::string path_;
  std::string& failure_;
};

class CheckedIOSystem : public Assimp::IOSystem {
 public:
  bool Exists(const char* path) const override { return access(path, F_OK) == 0; }
  char getOsSeparator() const override { return '/'; }
  Assimp::IOStream* Open(const char* path, const char* mode) override {
    std::FILE* file = std::fopen(path, mode);
    if (file == nullptr) {
      if (failure.empty()) failure = std::string(path) + ": " + std::strerror(errno);
      return nullptr;
    }
    return new CheckedStream(file, path, failure);
  }
  void Close(Assimp::IOStream* stream) override { delete stream; }

  std::string failure;  ///< the first write that failed, "path: reason"
};

aiMesh* to_assimp(const std::string& name, const TriangleMesh& mesh) {
  assert(!mesh.triangles.empty());
  auto out = std::make_unique<aiMesh>();
  out->mName = name;
  out->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
  out->mMaterialIndex = 0;
  out->mNumVertices = static_cast<unsigned>(mesh.vertices_m.size());
  out->mVertices = new aiVector3D[out->mNumVertices];
  for (unsigned i = 0; i < out->mNumVertices; ++i) {
    const Eigen::Vector3d& v = mesh.vertices_m[i];
    out->mVertices[i] =
        aiVector3D(static_cast<ai_real>(v.x()), static_cast<ai_real>(v.y()), static_cast<ai_real>(v.z()));
  }
  out->mNumFaces = static_cast<unsigned>(mesh.triangles.size());
  out->mFaces = new aiFace[out->mNumFaces];
  for (unsigned i = 0; i < out->mNumFaces; ++i) {
    aiFace& face = out->mFaces[i];
    face.mNumIndices = 3;
    face.mIndices = new unsigned[3];
    for (int k = 0; k < 3; ++k) face.mIndices[k] = static_cast<unsigned>(mesh.triangles[i][k]);
  }
  return out.release();
}

}  // namespace

bool mesh_export_built() { return true; }

void require_mesh_export() {}

MeshExportFormat mesh_export_format(const std::string& path) {
  const std::string extension = lower_extension(path);
  Assimp::Exporter exporter;
  const auto preferred = kPreferredFormat.find(extension);
  for (std::size_t i = 0; i < exporter.GetExportFormatCount(); ++i) {
    const aiExportFormatDesc* desc = exporter.GetExportFormatDescription(i);
    const bool match =
        preferred != kPreferredFormat.end() ? preferred->second == desc->id : extension == desc->fileExtension;
    if (match) return {desc->id, desc->description};
  }
  std::string known;
  for (std::size_t i = 0; i < exporter.GetExportFormatCount(); ++i) {
    const std::string candidate = std::string(" .") + exporter.GetExportFormatDescription(i)->fileExtension;
    if ((known + " ").find(candidate + " ") == std::string::npos) known += candidate;
  }
  throw std::runtime_error("cannot write mesh file '" + path + "': unknown extension '" + extension +
                           "'; use .obj .ply .stl .glb .gltf (or another extension assimp writes:" + known + ")");
}

void export_meshes(const std::vector<std::pair<std::string, TriangleMesh>>& named_meshes, const std::string& path) {
  const MeshExportFormat format = mesh_export_format(path);
  assert(!named_meshes.empty());

  // aiScene's destructor frees everything hung on it with delete/delete[].
  aiScene scene;
  scene.mNumMaterials = 1;
  scene.mMaterials = new aiMaterial* [1] { new aiMaterial };
  scene.mNumMeshes = static_cast<unsigned>(named_meshes.size());
  scene.mMeshes = new aiMesh*[scene.mNumMeshes];
  scene.mRootNode = new aiNode("railjoint");
  scene.mRootNode->mNumChildren = scene.mNumMeshes;
  scene.mRootNode->mChildren = new aiNode*[scene.mNumMeshes];
  for (unsigned i = 0; i < scene.mNumMeshes; ++i) {
    const auto& [name, mesh] = named_meshes[i];
    scene.mMeshes[i] = to_assimp(name, mesh);
    aiNode* node = new aiNode(name);
    node->mParent = scene.mRootNode;
    node->mNumMeshes = 1;
    node->mMeshes = new unsigned[1]{i};
    scene.mRootNode->mChildren[i] = node;
  }

  Assimp::Exporter exporter;
  auto* files = new CheckedIOSystem;  // the exporter owns it
  exporter.SetIOHandler(files);
  const aiReturn status = exporter.Export(&scene, format.assimp_id, path);
  if (status != aiReturn_SUCCESS || !files->failure.empty()) {
    throw std::runtime_error("cannot write mesh file '" + path + "' (" + format.description +
                             "): " + (files->failure.empty() ? std::string(exporter.GetErrorString()) : files->failure));
  }
}

}  // namespace railjoint
