#include "parashade/geometry_stage.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/gtc/matrix_transform.hpp>

#include "parashade/parallel.hpp"
#include "parashade/vertex_lighting.hpp"
#include "parashade/vertex_snap.hpp"
#include "parashade/vertex_world.hpp"

namespace parashade {
namespace {

float plane_distance(const glm::vec4& c, int plane) {
  switch (plane) {
    case kNear: return c.z + c.w;
    case kFar: return c.w - c.z;
    case kLeft: return c.x + kGuardBand * c.w;
    case kRight: return kGuardBand * c.w - c.x;
    case kBottom: return c.y + kGuardBand * c.w;
    default: return kGuardBand * c.w - c.y;
  }
}

struct ClipVertex {
  std::uint32_t index;  // scene vertex index, or kNewVertex
  glm::vec4 clip;
  glm::vec3 world, normal, color;
};
constexpr std::uint32_t kNewVertex = 0x80000000u;  // flag on chunk-local indices of clip-made vertices

struct Needs {
  bool world, normal, color, flat;
};

// Where an object's vertices come from: world position, unit normal and (Gouraud) lit colour of one of
// its vertices, computed on demand. Lighting is the costly part of the vertex stage, so it runs only
// for vertices of triangles that survive culling (or that clipping needs).
struct VertexSource {
  const Mesh* mesh = nullptr;
  glm::mat4 model{1.0f};
  glm::mat4 model_vp{1.0f};  // to clip space
  glm::mat3 normal_matrix{1.0f};
  std::uint32_t material = 0;
  std::uint32_t base = 0;  // index of the object's first vertex in the frame

  glm::vec3 world(std::size_t i) const { return world_position(model, mesh->positions[i]); }
  // The vertex stage's clip position, recomputed (the same bits: transform_vertices' lanes are this
  // product) for the few vertices clipping needs, instead of 16 bytes kept per scene vertex.
  glm::vec4 clip(std::size_t i) const { return model_vp * glm::vec4(mesh->positions[i], 1.0f); }
  glm::vec3 normal(std::size_t i) const { return unit_normal(normal_matrix, mesh->normals[i]); }
};

// Work of one chunk of input triangles, merged in chunk order so the output order is deterministic.
struct ChunkOutput {
  std::vector<glm::uvec3> triangles;  // all of one object, so of one material (ChunkJob::object)
  std::vector<glm::vec3> flat_color;
  std::vector<ClipVertex> new_vertices;
  std::vector<Snapped> new_snapped;
  std::vector<std::uint32_t> face;  // per triangle: its scene face (ScreenGeometry::face)
  GeometryStats stats;
};

struct ChunkJob {
  std::size_t object;
  std::size_t first, count;  // triangles of that object
  std::size_t face_first;    // scene face index of `first` (objects' faces concatenated)
};

class Assembler {
 public:
  Assembler(const Scene& scene, const ScreenGeometry& g, const Needs& needs, const VertexLighting& lighting,
            const std::vector<VertexSource>& sources, std::vector<std::uint8_t>& used)
      : scene_(scene), g_(g), needs_(needs), lighting_(lighting), sources_(sources), used_(used) {}

  void run(const ChunkJob& job, std::uint32_t vertex_base, ChunkOutput& out) const {
    const Object& obj = scene_.objects[job.object];
    const VertexSource& src = sources_[job.object];
    const Mesh& mesh = *obj.mesh;
    out.triangles.reserve(job.count);
    out.face.reserve(job.count);
    if (needs_.flat) out.flat_color.reserve(job.count);
    out.stats.triangles_in += job.count;
    // Plain pointers: the used flags are bytes, and a store through them may alias anything.
    const glm::uvec3* triangles = mesh.triangles.data();
    const std::uint8_t* outcode = g_.outcode.data();
    const glm::ivec2* xy = g_.xy.data();
    std::uint8_t* used = needs_.color ? used_.data() : nullptr;
    FlatLanes flat_lanes{this, obj.material, out.flat_color, {}, {}, {}};
    for (std::size_t t = job.first; t < job.first + job.count; ++t) {
      glm::uvec3 tri = triangles[t] + glm::uvec3(vertex_base);
      const std::uint32_t face = std::uint32_t(job.face_first + (t - job.first));
      const std::uint8_t o0 = outcode[tri.x], o1 = outcode[tri.y], o2 = outcode[tri.z];
      if ((o0 | o1 | o2) == 0) {  // the common case: inside the guard band, scene vertices only
        const std::int64_t area2 = area2_of(glm::i64vec2(xy[tri.x]), glm::i64vec2(xy[tri.y]), glm::i64vec2(xy[tri.z]));
        if (!survives(area2, out)) continue;
        if (needs_.flat) flat_lanes.add(tri);  // in the scene's vertex order
        if (used) {  // the same value from any thread
          __atomic_store_n(&used[tri.x], std::uint8_t(1), __ATOMIC_RELAXED);
          __atomic_store_n(&used[tri.y], std::uint8_t(1), __ATOMIC_RELAXED);
          __atomic_store_n(&used[tri.z], std::uint8_t(1), __ATOMIC_RELAXED);
        }
        // Oriented from registers: std::swap on `tri` made GCC store its halves separately and reload them
        // as one 8-byte word, a store-forwarding stall on every triangle.
        const bool flip = area2 < 0;
        out.triangles.emplace_back(tri.x, flip ? tri.z : tri.y, flip ? tri.y : tri.z);
        out.face.push_back(face);
        continue;
      }
      if ((o0 | o1 | o2) & kNonFinite) {  // no meaningful position to clip or draw
        ++out.stats.non_finite;
        continue;
      }
      if (o0 & o1 & o2) {
        ++out.stats.outside;
        continue;
      }
      FlatValue flat{this, obj.material, tri};
      ++out.stats.clipped;
      clip_and_emit(tri, std::uint8_t(o0 | o1 | o2), flat, src, out);
      out.face.resize(out.triangles.size(), face);
    }
    flat_lanes.finish();
  }

 private:
  // Flat: the triangle's value, computed when its first (sub-)triangle survives culling, then reused.
  struct FlatValue {
    const Assembler* assembler;
    std::uint32_t material;
    glm::uvec3 tri;
    bool known = false;
    glm::vec3 value{0.0f};
    glm::vec3 get() {
      if (!known) value = assembler->flat_value(material, tri), known = true;
      return value;
    }
  };

  glm::vec3 flat_value(std::uint32_t material, glm::uvec3 tri) const {
    glm::vec3 p, n;
    flat_point(tri, p, n);
    return lighting_.shade(material, p, n);
  }

  // Where flat_value lights a triangle: its centroid and unit face normal.
  void flat_point(glm::uvec3 tri, glm::vec3& p, glm::vec3& n) const {
    const glm::vec3 a = g_.world[tri.x], b = g_.world[tri.y], c = g_.world[tri.z];
    n = glm::cross(b - a, c - a);
    float len = glm::length(n);
    if (!(len > 0.0f) && needs_.normal) {  // zero-area in world space: fall back to the vertex normals
      n = g_.normal[tri.x] + g_.normal[tri.y] + g_.normal[tri.z];
      len = glm::length(n);
    }
    n = len > 0.0f ? n / len : glm::vec3(0.0f, 0.0f, 1.0f);
    p = (a + b + c) / 3.0f;
  }

  // Flat values of a chunk's unclipped triangles, lit VertexLighting::kLanes at a time (lit one by one,
  // they took sphere_2m's flat geometry stage to 34 ms, 27 in lanes); the same bits as flat_value. Each
  // value's slot is reserved in order, so clipped triangles' values can go between.
  struct FlatLanes {
    static constexpr int kLanes = VertexLighting::kLanes;
    const Assembler* assembler;
    std::uint32_t material;
    std::vector<glm::vec3>& values;
    std::size_t slot[kLanes];
    glm::vec3 p[kLanes], n[kLanes];
    int lanes = 0;
    void add(glm::uvec3 tri) {
      slot[lanes] = values.size();
      values.emplace_back();
      assembler->flat_point(tri, p[lanes], n[lanes]);
      if (++lanes < kLanes) return;
      glm::vec3 lit[kLanes];
      assembler->lighting_.shade_lanes(material, p, n, lit);
      for (int k = 0; k < kLanes; ++k) values[slot[k]] = lit[k];
      lanes = 0;
    }
    void finish() {
      for (int k = 0; k < lanes; ++k) values[slot[k]] = assembler->lighting_.shade(material, p[k], n[k]);
      lanes = 0;
    }
  };

  glm::ivec2 xy_of(std::uint32_t v, const ChunkOutput& out) const {
    return (v & kNewVertex) ? out.new_snapped[v & ~kNewVertex].xy : g_.xy[v];
  }

  // Twice the signed screen area; 0 drops the triangle, and with culling so does > 0 (a back face:
  // counter-clockwise in NDC, i.e. front, is clockwise on the y-down screen, area2 < 0).
  bool survives(std::int64_t area2, ChunkOutput& out) const {
    if (area2 == 0) {
      ++out.stats.zero_area;
      return false;
    }
    if (area2 > 0 && scene_.cull_backfaces) {
      ++out.stats.culled_backface;
      return false;
    }
    return true;
  }

  static std::int64_t area2_of(glm::i64vec2 p0, glm::i64vec2 p1, glm::i64vec2 p2) {
    return (p1.x - p0.x) * (p2.y - p0.y) - (p1.y - p0.y) * (p2.x - p0.x);
  }

  void mark_used(std::uint32_t v) const {
    if (!(v & kNewVertex)) __atomic_store_n(&used_[v], std::uint8_t(1), __ATOMIC_RELAXED);  // same value from any thread
  }

  void emit(glm::uvec3 tri, FlatValue& flat, ChunkOutput& out) const {
    const std::int64_t area2 = area2_of(glm::i64vec2(xy_of(tri.x, out)), glm::i64vec2(xy_of(tri.y, out)),
                                        glm::i64vec2(xy_of(tri.z, out)));
    if (!survives(area2, out)) return;
    if (area2 < 0) std::swap(tri.y, tri.z);
    if (needs_.color)
      for (std::uint32_t v : {tri.x, tri.y, tri.z}) mark_used(v);
    out.triangles.push_back(tri);
    if (needs_.flat) out.flat_color.push_back(flat.get());
  }

  ClipVertex clip_vertex(std::uint32_t v, const VertexSource& src) const {
    ClipVertex c{v, src.clip(v - src.base), glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f)};
    if (needs_.world) c.world = g_.world[v];
    if (needs_.normal) c.normal = g_.normal[v];
    if (needs_.color) {  // not lit yet (lighting follows assembly): light this vertex now
      const std::size_t i = v - src.base;
      c.color = lighting_.shade(src.material, src.world(i), src.normal(i));
    }
    return c;
  }

  // Interpolates from the inside vertex toward the outside one, so the two triangles sharing an edge
  // compute bit-identical intersection points (watertight across clip boundaries).
  static ClipVertex intersect(const ClipVertex& in, const ClipVertex& out, int plane) {
    const float d_in = plane_distance(in.clip, plane), d_out = plane_distance(out.clip, plane);
    const float t = d_in / (d_in - d_out);
    ClipVertex r;
    r.index = kNewVertex;
    r.clip = in.clip + t * (out.clip - in.clip);
    r.world = in.world + t * (out.world - in.world);
    r.normal = in.normal + t * (out.normal - in.normal);
    r.color = in.color + t * (out.color - in.color);
    return r;
  }

  void clip_and_emit(glm::uvec3 tri, std::uint8_t planes, FlatValue& flat,
                     const VertexSource& src, ChunkOutput& out) const {
    // Sutherland–Hodgman against each plane the triangle reaches beyond; at most 3 + 6 vertices.
    ClipVertex buffer_a[12], buffer_b[12];
    ClipVertex* poly = buffer_a;
    ClipVertex* next = buffer_b;
    int n = 3;
    poly[0] = clip_vertex(tri.x, src);
    poly[1] = clip_vertex(tri.y, src);
    poly[2] = clip_vertex(tri.z, src);
    for (int plane = kNear; plane <= kTop && n >= 3; plane <<= 1) {
      if (!(planes & plane)) continue;
      int m = 0;
      for (int i = 0; i < n; ++i) {
        const ClipVertex& a = poly[i];
        const ClipVertex& b = poly[(i + 1) % n];
        const bool a_in = plane_distance(a.clip, plane) >= 0.0f;
        const bool b_in = plane_distance(b.clip, plane) >= 0.0f;
        if (a_in) next[m++] = a;
        if (a_in != b_in) next[m++] = a_in ? intersect(a, b, plane) : intersect(b, a, plane);
      }
      std::swap(poly, next);
      n = m;
    }
    if (n < 3) {
      ++out.stats.outside;
      return;
    }
    std::uint32_t ids[12];
    for (int i = 0; i < n; ++i) {
      if (poly[i].index != kNewVertex) {
        ids[i] = poly[i].index;
        continue;
      }
      ids[i] = kNewVertex | std::uint32_t(out.new_vertices.size());
      out.new_vertices.push_back(poly[i]);
      out.new_snapped.push_back(snap(poly[i].clip, g_.width, g_.height));
    }
    for (int i = 1; i + 1 < n; ++i) emit({ids[0], ids[i], ids[i + 1]}, flat, out);
  }

  const Scene& scene_;
  const ScreenGeometry& g_;
  const Needs needs_;
  const VertexLighting& lighting_;
  const std::vector<VertexSource>& sources_;
  std::vector<std::uint8_t>& used_;  // Gouraud: per scene vertex, 1 when a surviving triangle uses it
};

// Consecutive vertices of one object: a work item of the vertex stage or of lighting.
struct ObjectRange {
  std::size_t object, first, last;
};

// Every object's vertices cut into ranges by balanced_chunk(its count, min_chunk, max_chunk).
void object_ranges(const std::vector<VertexSource>& sources, std::size_t min_chunk, std::size_t max_chunk,
                   std::vector<ObjectRange>& out) {
  out.clear();
  for (std::size_t o = 0; o < sources.size(); ++o) {
    const std::size_t count = sources[o].mesh->positions.size(), chunk = balanced_chunk(count, min_chunk, max_chunk);
    for (std::size_t first = 0; first < count; first += chunk)
      out.push_back({o, first, std::min(count, first + chunk)});
  }
}

template <typename T>
void resize_if(std::vector<T>& v, bool keep, std::size_t n) {
  if (keep)
    v.resize(n);
  else
    v.clear();
}

}  // namespace

struct GeometryScratch {
  std::vector<std::uint32_t> vertex_base;
  std::vector<VertexSource> sources;
  std::vector<ChunkJob> jobs;
  std::vector<ChunkOutput> outputs;  // cleared, not freed, between frames
  std::vector<std::uint8_t> used;
  std::vector<std::size_t> tri_offset, new_offset;
  std::vector<ObjectRange> vertex_ranges, light_ranges;
};

glm::mat4 view_projection(const Scene& scene) {
  const Camera& c = scene.camera;
  const float aspect = float(scene.width) / float(scene.height);
  const glm::mat4 view = glm::lookAt(c.position, c.target, c.up);
  glm::mat4 proj;
  if (c.projection == Projection::perspective) {
    proj = glm::perspective(glm::radians(c.fov_y_degrees), aspect, c.near_plane, c.far_plane);
  } else {
    const float h = 0.5f * c.ortho_height, w = h * aspect;
    proj = glm::ortho(-w, w, -h, h, c.near_plane, c.far_plane);
  }
  return proj * view;
}

namespace {

// Which per-vertex attributes the method (and a reference render or a vertex-colour request) reads.
Needs needs_of(const GeometryRequest& request) {
  const Method method = request.method;
  const bool per_pixel = method == Method::phong || method == Method::combined;
  return {method == Method::flat || per_pixel || request.for_reference, per_pixel || request.for_reference,
          method == Method::gouraud || request.vertex_colours, method == Method::flat};
}

// Each object's first vertex in the frame (objects' vertices concatenated); returns the scene's vertex count.
std::size_t number_vertices(const Scene& scene, std::vector<std::uint32_t>& vertex_base) {
  std::size_t vertex_count = 0;
  vertex_base.clear();
  for (const Object& o : scene.objects) {
    vertex_base.push_back(std::uint32_t(vertex_count));
    vertex_count += o.mesh->positions.size();
  }
  return vertex_count;
}

// The per-vertex arrays sized for `count` vertices; those the method does not read are emptied.
void size_vertex_arrays(ScreenGeometry& g, const Needs& needs, std::size_t count) {
  g.xy.resize(count);
  g.depth.resize(count);
  g.inv_w.resize(count);
  resize_if(g.world, needs.world, count);
  resize_if(g.normal, needs.normal, count);
  resize_if(g.color, needs.color, count);
}

// Vertex stage: every scene vertex's outcode, snapped position, depth and 1/w, and (if read) its world
// position and unit normal. Lighting waits for assembly, which knows the vertices that are used.
void transform_scene_vertices(const Scene& scene, const Needs& needs, std::size_t vertex_count,
                              GeometryScratch& scratch, ScreenGeometry& g) {
  const glm::mat4 vp = view_projection(scene);
  g.outcode.resize(vertex_count);
  size_vertex_arrays(g, needs, vertex_count);
  std::vector<VertexSource>& sources = scratch.sources;
  sources.resize(scene.objects.size());
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    const Object& obj = scene.objects[o];
    sources[o] = {obj.mesh.get(), obj.model, vp * obj.model, glm::transpose(glm::inverse(glm::mat3(obj.model))),
                  obj.material, scratch.vertex_base[o]};
  }
  // One parallel_for over every object's vertices (a wake-up of the pool per object costs more than a
  // small object's work). Ranges of at least 4096 vertices (~40 ns each): a scene of a few thousand
  // vertices stays on one thread.
  object_ranges(sources, 4096, 8192, scratch.vertex_ranges);
  parallel_for(scratch.vertex_ranges.size(), [&](std::size_t r) {
    const ObjectRange range = scratch.vertex_ranges[r];
    const VertexSource& src = sources[range.object];
    const glm::mat4 m = src.model_vp;
    const std::size_t at = src.base + range.first;
    transform_vertices(m, src.mesh->positions.data() + range.first, range.last - range.first, g.width, g.height,
                       {nullptr, g.outcode.data() + at, g.xy.data() + at, g.depth.data() + at,
                        g.inv_w.data() + at});
    if (needs.world || needs.normal)
      world_and_normals(src.model, src.normal_matrix, src.mesh->positions.data() + range.first,
                        needs.normal ? src.mesh->normals.data() + range.first : nullptr, range.last - range.first,
                        needs.world ? g.world.data() + at : nullptr, needs.normal ? g.normal.data() + at : nullptr);
  });
}

// Primitive assembly's work items: every object's triangles in chunks, and an empty output for each.
void plan_chunks(const Scene& scene, GeometryScratch& scratch) {
  std::vector<ChunkJob>& jobs = scratch.jobs;
  jobs.clear();
  std::size_t face_base = 0;
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    // Chunks of 16384 triangles (~6 ns each): a smaller one is not worth waking a worker for.
    const std::size_t count = scene.objects[o].mesh->triangles.size(), chunk = balanced_chunk(count, 16384, 16384);
    for (std::size_t first = 0; first < count; first += chunk)
      jobs.push_back({o, first, std::min(chunk, count - first), face_base + first});
    face_base += count;
  }
  std::vector<ChunkOutput>& outputs = scratch.outputs;
  if (outputs.size() < jobs.size()) outputs.resize(jobs.size());
  for (std::size_t j = 0; j < jobs.size(); ++j) {
    ChunkOutput& out = outputs[j];
    out.triangles.clear();
    out.face.clear();
    out.flat_color.clear();
    out.new_vertices.clear();
    out.new_snapped.clear();
    out.stats = {};
  }
}

// The frame's sizes once the chunks are assembled.
struct FrameCounts {
  std::size_t triangles, vertices;  // vertices: the scene's and the clip-made ones
};

// Where each chunk's triangles and clip-made vertices go in the frame (in chunk order), and the chunks'
// stats summed into g.stats.
FrameCounts place_chunks(std::size_t vertex_count, GeometryScratch& scratch, ScreenGeometry& g) {
  std::size_t tri_total = 0, new_total = 0;
  const std::size_t chunks = scratch.jobs.size();
  scratch.tri_offset.resize(chunks);
  scratch.new_offset.resize(chunks);
  for (std::size_t j = 0; j < chunks; ++j) {
    const ChunkOutput& out = scratch.outputs[j];
    scratch.tri_offset[j] = tri_total;
    scratch.new_offset[j] = vertex_count + new_total;
    tri_total += out.triangles.size();
    new_total += out.new_vertices.size();
    const GeometryStats& s = out.stats;
    g.stats.triangles_in += s.triangles_in;
    g.stats.culled_backface += s.culled_backface;
    g.stats.zero_area += s.zero_area;
    g.stats.outside += s.outside;
    g.stats.clipped += s.clipped;
    g.stats.non_finite += s.non_finite;
  }
  g.stats.triangles_out = tri_total;
  return {tri_total, vertex_count + new_total};
}

// Gouraud: lights the vertices of one range that surviving triangles use, VertexLighting::kLanes at a
// time; the others keep a zero colour.
void light_used_vertices(const VertexSource& src, const ObjectRange& range, const std::vector<std::uint8_t>& used,
                         const VertexLighting& lighting, ScreenGeometry& g) {
  constexpr int kLanes = VertexLighting::kLanes;
  std::size_t lane_vertex[kLanes];
  glm::vec3 position[kLanes], normal[kLanes], p[kLanes], n[kLanes], colour[kLanes];
  int lanes = 0;
  for (std::size_t i = range.first; i < range.last; ++i) {
    const std::size_t v = src.base + i;
    if (!used[v]) {
      g.color[v] = glm::vec3(0.0f);
      continue;
    }
    lane_vertex[lanes] = v;
    position[lanes] = src.mesh->positions[i];
    normal[lanes] = src.mesh->normals[i];
    if (++lanes < kLanes) continue;
    world_and_normals(src.model, src.normal_matrix, position, normal, kLanes, p, n);
    lighting.shade_lanes(src.material, p, n, colour);
    for (int k = 0; k < kLanes; ++k) g.color[lane_vertex[k]] = colour[k];
    lanes = 0;
  }
  world_and_normals(src.model, src.normal_matrix, position, normal, std::size_t(lanes), p, n);
  for (int k = 0; k < lanes; ++k) g.color[lane_vertex[k]] = lighting.shade(src.material, p[k], n[k]);
}

// Copies chunk j's clip-made vertices and its triangles (chunk-local indices renumbered) to their places.
void merge_chunk(const Scene& scene, const Needs& needs, const GeometryScratch& scratch, std::size_t j,
                 ScreenGeometry& g) {
  const ChunkOutput& out = scratch.outputs[j];
  const std::uint32_t base = std::uint32_t(scratch.new_offset[j]);
  for (std::size_t k = 0; k < out.new_vertices.size(); ++k) {
    const std::size_t v = base + k;
    g.xy[v] = out.new_snapped[k].xy;
    g.depth[v] = out.new_snapped[k].depth;
    g.inv_w[v] = out.new_snapped[k].inv_w;
    if (needs.world) g.world[v] = out.new_vertices[k].world;
    if (needs.normal) g.normal[v] = out.new_vertices[k].normal;
    if (needs.color) g.color[v] = out.new_vertices[k].color;
  }
  const std::uint32_t material = scene.objects[scratch.jobs[j].object].material;
  const auto remap = [base](std::uint32_t v) { return (v & kNewVertex) ? base + (v & ~kNewVertex) : v; };
  const std::size_t first = scratch.tri_offset[j];
  for (std::size_t t = 0; t < out.triangles.size(); ++t) {
    const glm::uvec3 tri = out.triangles[t];
    g.triangles[first + t] = {remap(tri.x), remap(tri.y), remap(tri.z)};
    g.material[first + t] = material;
    g.face[first + t] = out.face[t];
    if (needs.flat) g.flat_color[first + t] = out.flat_color[t];
  }
}

}  // namespace

void build_screen_geometry(const Scene& scene, const GeometryRequest& request, ScreenGeometry& g) {
  const Needs needs = needs_of(request);
  const VertexLighting lighting(scene);
  g.width = scene.width;
  g.height = scene.height;
  g.stats = {};
  if (!g.scratch.ptr) g.scratch.ptr = std::make_shared<GeometryScratch>();
  GeometryScratch& scratch = *g.scratch.ptr;
  const std::size_t vertex_count = number_vertices(scene, scratch.vertex_base);
  transform_scene_vertices(scene, needs, vertex_count, scratch, g);

  // Primitive assembly in chunks, merged in order.
  plan_chunks(scene, scratch);
  std::vector<std::uint8_t>& used = scratch.used;
  used.assign(needs.color ? vertex_count : 0, 0);
  const Assembler assembler(scene, g, needs, lighting, scratch.sources, used);
  const std::vector<ChunkJob>& jobs = scratch.jobs;
  parallel_for(jobs.size(),
               [&](std::size_t j) { assembler.run(jobs[j], scratch.vertex_base[jobs[j].object], scratch.outputs[j]); });
  const FrameCounts total = place_chunks(vertex_count, scratch, g);
  size_vertex_arrays(g, needs, total.vertices);
  g.triangles.resize(total.triangles);
  g.material.resize(total.triangles);
  g.face.resize(total.triangles);
  g.flat_color.resize(needs.flat ? total.triangles : 0);

  // Gouraud: light the vertices the surviving triangles use, in the same parallel_for as the merge of the
  // chunks (one wake-up of the pool, not two). Lighting ranges of 8192 vertices (~33 ns for each one lit;
  // a culled mesh lights about half).
  if (needs.color)
    object_ranges(scratch.sources, 8192, 8192, scratch.light_ranges);
  else
    scratch.light_ranges.clear();
  const std::size_t light_items = scratch.light_ranges.size(), items = light_items + jobs.size();
  const bool worth_waking = items > 2;  // else ~0.1 ms of work or less
  parallel_for_if(worth_waking, items, [&](std::size_t item) {
    if (item < light_items) {
      const ObjectRange& range = scratch.light_ranges[item];
      light_used_vertices(scratch.sources[range.object], range, used, lighting, g);
    } else {
      merge_chunk(scene, needs, scratch, item - light_items, g);
    }
  });
}

}  // namespace parashade
