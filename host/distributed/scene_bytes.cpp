#include "scene_bytes.hpp"

#include <algorithm>
#include <cstring>
#include <memory>
#include <map>
#include <string>
#include <type_traits>

#include "parashade/errors.hpp"

namespace parashade::distributed {
namespace {

class Writer {
 public:
  std::vector<char> bytes;
  template <class T>
  void put(const T& v) {
    // glm's vectors and matrices (no trivial copy under GLM_FORCE_CTOR_INIT) are plain floats in a row.
    static_assert(std::is_standard_layout_v<T>, "bytes of a plain value");
    const char* p = reinterpret_cast<const char*>(&v);
    bytes.insert(bytes.end(), p, p + sizeof(T));
  }
  template <class T>
  void put_vector(const std::vector<T>& v) {
    put(std::uint64_t(v.size()));
    const char* p = reinterpret_cast<const char*>(v.data());
    bytes.insert(bytes.end(), p, p + v.size() * sizeof(T));
  }
  void put_string(const std::string& s) { put_vector(std::vector<char>(s.begin(), s.end())); }
};

class Reader {
 public:
  explicit Reader(const std::vector<char>& b) : bytes_(b) {}
  template <class T>
  T get() {
    T v;
    take(&v, sizeof(T));
    return v;
  }
  template <class T>
  std::vector<T> get_vector() {
    const auto n = get<std::uint64_t>();
    if (n > (bytes_.size() - at_) / sizeof(T)) fail();
    std::vector<T> v(n);
    take(v.data(), n * sizeof(T));
    return v;
  }
  std::string get_string() {
    const auto v = get_vector<char>();
    return {v.begin(), v.end()};
  }
  void finish() const {
    if (at_ != bytes_.size()) fail();
  }

 private:
  void take(void* out, std::size_t n) {
    if (n > bytes_.size() - at_) fail();
    std::memcpy(out, bytes_.data() + at_, n);
    at_ += n;
  }
  [[noreturn]] void fail() const {
    throw InputError("the scene rank 0 sent is " + std::to_string(bytes_.size()) + " bytes, which do not parse");
  }
  const std::vector<char>& bytes_;
  std::size_t at_ = 0;
};

}  // namespace

std::vector<char> scene_to_bytes(const Scene& scene, const std::vector<std::uint32_t>& global_face) {
  Writer w;
  w.put_string(scene.name);
  w.put(scene.width);
  w.put(scene.height);
  w.put(scene.background);
  w.put(scene.ambient_light);
  w.put(scene.camera);
  w.put_vector(scene.lights);
  w.put(std::uint64_t(scene.materials.size()));
  for (const Material& m : scene.materials) {
    w.put_string(m.name);
    w.put(m.ambient);
    w.put(m.diffuse);
    w.put(m.specular);
    w.put(m.shininess);
  }
  // Meshes once each (objects may share one), then the objects naming theirs.
  std::map<const Mesh*, std::uint64_t> index;
  std::vector<const Mesh*> meshes;
  for (const Object& o : scene.objects)
    if (index.emplace(o.mesh.get(), meshes.size()).second) meshes.push_back(o.mesh.get());
  w.put(std::uint64_t(meshes.size()));
  for (const Mesh* m : meshes) {
    w.put_vector(m->positions);
    w.put_vector(m->normals);
    w.put_vector(m->triangles);
  }
  w.put(std::uint64_t(scene.objects.size()));
  for (const Object& o : scene.objects) {
    w.put_string(o.name);
    w.put(index.at(o.mesh.get()));
    w.put(o.model);
    w.put(o.material);
  }
  w.put(std::uint8_t(scene.cull_backfaces));
  w.put(std::uint8_t(scene.local_viewer));
  w.put_vector(global_face);
  return std::move(w.bytes);
}

Scene scene_from_bytes(const std::vector<char>& bytes, std::vector<std::uint32_t>& global_face) {
  Reader r(bytes);
  Scene s;
  s.name = r.get_string();
  s.width = r.get<int>();
  s.height = r.get<int>();
  s.background = r.get<glm::vec3>();
  s.ambient_light = r.get<glm::vec3>();
  s.camera = r.get<Camera>();
  s.lights = r.get_vector<Light>();
  const auto materials = r.get<std::uint64_t>();
  for (std::uint64_t i = 0; i < materials && i < bytes.size(); ++i) {
    Material m;
    m.name = r.get_string();
    m.ambient = r.get<glm::vec3>();
    m.diffuse = r.get<glm::vec3>();
    m.specular = r.get<glm::vec3>();
    m.shininess = r.get<float>();
    s.materials.push_back(std::move(m));
  }
  std::vector<std::shared_ptr<const Mesh>> meshes(std::min<std::uint64_t>(r.get<std::uint64_t>(), bytes.size()));
  for (auto& shared : meshes) {
    auto m = std::make_shared<Mesh>();
    m->positions = r.get_vector<glm::vec3>();
    m->normals = r.get_vector<glm::vec3>();
    m->triangles = r.get_vector<glm::uvec3>();
    shared = std::move(m);
  }
  const auto objects = r.get<std::uint64_t>();
  for (std::uint64_t i = 0; i < objects && i < bytes.size(); ++i) {
    Object o;
    o.name = r.get_string();
    const auto mesh = r.get<std::uint64_t>();
    if (mesh >= meshes.size()) throw InputError("the scene rank 0 sent names mesh " + std::to_string(mesh) + " of " +
                                                std::to_string(meshes.size()));
    o.mesh = meshes[mesh];
    o.model = r.get<glm::mat4>();
    o.material = r.get<std::uint32_t>();
    s.objects.push_back(std::move(o));
  }
  s.cull_backfaces = r.get<std::uint8_t>() != 0;
  s.local_viewer = r.get<std::uint8_t>() != 0;
  global_face = r.get_vector<std::uint32_t>();
  r.finish();
  return s;
}

}  // namespace parashade::distributed
