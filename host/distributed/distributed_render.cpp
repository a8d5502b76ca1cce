// One frame across MPI ranks, sort-last and sort-first (docs/distributed.md).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <memory>
#include <numeric>

#include "composite.hpp"
#include "mpi_session.hpp"
#include "scene_bytes.hpp"
#include "parashade/device.hpp"
#include "parashade/distributed.hpp"
#include "parashade/errors.hpp"
#include "parashade/frame_pipeline.hpp"
#include "parashade/report.hpp"
#include "parashade/report_header.hpp"
#include "parashade/setup.hpp"
#include "parashade/statistics.hpp"
// kernels/plan_key.h's PLAN_NO_KEY (that header is OpenCL C).
constexpr std::uint64_t PLAN_NO_KEY = ~std::uint64_t(0);

namespace parashade {

namespace distributed {
namespace {

KeyPixel key_pixel(const std::vector<char>& buf, std::size_t p, int bytes) {
  KeyPixel k;
  std::memcpy(&k, buf.data() + p * std::size_t(bytes), sizeof k);
  return k;
}

// What each rank measured in one frame (sent to rank 0 as doubles).
struct RankFigures {
  double faces = 0, records = 0, pixels = 0, won_pixels = 0, modeled_clocks = 0;
  double prepare_ms = 0, render_ms = 0, frame_ms = 0, composite_ms = 0, bytes_sent = 0;
  double band_first = 0, band_rows = 0, record_bytes = 0;
  double pack_ms = 0;  // sort-last: keys and colours into the composite's buffer (local, per pixel)
  double gather_ms = 0;  // the composite's gather to rank 0 (sort-last: after the reduce-scatter)
};
constexpr int kFigures = sizeof(RankFigures) / sizeof(double);

double peak_rss_mb() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  return 0;
}

double now_ms() { return MPI_Wtime() * 1e3; }

double prepare_of(const FrameTimings& t) { return t.geometry_ms + t.setup_ms + t.binning_ms + t.planning_ms; }

std::size_t record_bytes(const RenderOptions& o, std::size_t records) {
  return records * (triangle_record_bytes(o.method) + (o.arith.fixed ? sizeof(FixedPlanes) : 0));
}

// The scene's faces assigned to ranks by the planner's strategies, from the modeled cost of each face
// (the sum of its records' costs on the frame's unit; a face clipped into pieces has several records).
std::vector<std::uint16_t> assign_faces(const Scene& scene, const DistributedRender& job, int ranks, double* plan_ms) {
  const double t0 = now_ms();
  FrameConfig c = job.options;
  c.plan.reset();
  c.band_first = 0;
  c.band_rows = -1;
  FramePipeline pipeline;
  const PreparedFrame& f = pipeline.prepare_frame(scene, c);
  const std::vector<std::uint32_t>& face = pipeline.geometry().face;
  std::vector<std::uint64_t> cost(scene.triangle_count(), 0);
  for (std::size_t i = 0; i < f.records; ++i)
    cost[face[i]] += triangle_cost(f.arrays.triangles[i], c.unit(), job.setup_clocks).clocks;
  std::vector<int> owner;
  switch (job.rank_partition) {
    case Partition::round_robin: owner = assign_round_robin(cost.size(), ranks); break;
    case Partition::lpt: owner = assign_lpt(cost, ranks); break;
    case Partition::dynamic: {
      const std::size_t b = std::size_t(std::max(1, job.rank_batch));
      std::vector<std::uint64_t> batch((cost.size() + b - 1) / b, 0);
      for (std::size_t i = 0; i < cost.size(); ++i) batch[i / b] += cost[i];
      const std::vector<int> batch_owner = assign_in_order(batch, ranks);
      owner.resize(cost.size());
      for (std::size_t i = 0; i < cost.size(); ++i) owner[i] = batch_owner[i / b];
      break;
    }
    case Partition::tiles:
      throw UsageError("--rank-partition tiles: sort-last ranks take triangles, not screen tiles");
  }
  *plan_ms = now_ms() - t0;
  return std::vector<std::uint16_t>(owner.begin(), owner.end());
}

// The rank's share of the scene: per object, the faces it owns (in scene order) over the vertices they
// use (in their order), normals as loaded. `global_face` gets each kept face's index in the whole scene.
Scene share_of(const Scene& scene, const std::vector<std::uint16_t>& owner, int rank,
               std::vector<std::uint32_t>& global_face) {
  Scene out = scene;
  out.objects.clear();
  global_face.clear();
  std::size_t base = 0;
  for (const Object& obj : scene.objects) {
    const Mesh& m = *obj.mesh;
    std::vector<std::uint32_t> remap(m.positions.size(), ~0u);
    std::size_t faces = 0;
    for (std::size_t t = 0; t < m.triangles.size(); ++t)
      if (owner[base + t] == rank) {
        ++faces;
        for (int k = 0; k < 3; ++k) remap[m.triangles[t][k]] = 0;
      }
    if (faces) {
      auto mesh = std::make_shared<Mesh>();
      std::uint32_t next = 0;
      for (std::size_t v = 0; v < remap.size(); ++v)
        if (remap[v] == 0) {
          remap[v] = next++;
          mesh->positions.push_back(m.positions[v]);
          mesh->normals.push_back(m.normals[v]);
        }
      mesh->triangles.reserve(faces);
      for (std::size_t t = 0; t < m.triangles.size(); ++t)
        if (owner[base + t] == rank) {
          const glm::uvec3 tri = m.triangles[t];
          mesh->triangles.push_back({remap[tri.x], remap[tri.y], remap[tri.z]});
          global_face.push_back(std::uint32_t(base + t));
        }
      Object o = obj;
      o.mesh = std::move(mesh);
      out.objects.push_back(std::move(o));
    }
    base += m.triangles.size();
  }
  return out;
}

// Band of tile rows per rank in proportion to `speed` (equal while any is unmeasured), at least one row
// each while there are rows enough: the multi-device split's rule (split_renderer.cpp).
std::vector<std::pair<int, int>> bands(int tile_rows, const std::vector<double>& speed) {
  const int n = int(speed.size());
  const bool measured = std::all_of(speed.begin(), speed.end(), [](double s) { return s > 0; });
  double total = 0;
  for (double s : speed) total += measured ? s : 1.0;
  std::vector<std::pair<int, int>> out(n);
  int row = 0;
  double acc = 0;
  for (int k = 0; k < n; ++k) {
    acc += (measured ? speed[k] : 1.0) / total;
    const int left = n - k - 1;
    int end = k + 1 == n ? tile_rows : int(std::lround(acc * tile_rows));
    if (tile_rows >= n) end = std::clamp(end, row + 1, tile_rows - left);
    out[k] = {row, std::max(0, end - row)};
    row = std::max(row, end);
  }
  return out;
}

// One timed frame of one rank: what the model of docs/distributed.md is validated against.
nlohmann::json frame_json(const RankFigures& f) {
  return {{"prepare_ms", f.prepare_ms}, {"render_ms", f.render_ms}, {"pack_ms", f.pack_ms},
          {"composite_ms", f.composite_ms}, {"gather_ms", f.gather_ms}, {"rank_frame_ms", f.frame_ms}};
}

void check_scatter_size(const std::vector<std::vector<char>>& parts) {
  std::size_t total = 0;
  for (const auto& p : parts) total += p.size();
  if (total > std::size_t(INT32_MAX))
    throw InputError("the scene's shares are " + std::to_string(total >> 20) +
                     " MB, more than one MPI_Scatterv sends (2 GB): use --read-scene every-rank");
}

// Rank 0's bytes to every rank with MPI_Scatterv (each rank gets its part of `parts`, empty elsewhere;
// check_scatter_size has passed on rank 0).
std::vector<char> scatter_parts(MpiSession& mpi, const std::vector<std::vector<char>>& parts) {
  std::vector<int> counts(mpi.rank == 0 ? mpi.size : 0), displs(counts.size());
  std::vector<char> all;
  if (mpi.rank == 0) {
    std::size_t total = 0;
    for (int r = 0; r < mpi.size; ++r) {
      counts[r] = int(parts[r].size());
      displs[r] = int(total);
      total += parts[r].size();
    }
    all.reserve(total);
    for (const auto& p : parts) all.insert(all.end(), p.begin(), p.end());
  }
  int mine = 0;
  MPI_Scatter(counts.data(), 1, MPI_INT, &mine, 1, MPI_INT, 0, mpi.comm);
  std::vector<char> out(static_cast<std::size_t>(mine));
  MPI_Scatterv(all.data(), counts.data(), displs.data(), MPI_CHAR, out.data(), mine, MPI_CHAR, 0, mpi.comm);
  return out;
}

nlohmann::json figures_json(const RankFigures& f, int rank, Distribute mode) {
  nlohmann::json j = {{"rank", rank},
                      {"records", f.records},
                      {"record_bytes", f.record_bytes},
                      {"pixels", f.pixels},
                      {"prepare_ms", f.prepare_ms},
                      {"render_ms", f.render_ms},
                      {"rank_frame_ms", f.frame_ms},
                      {"composite_ms", f.composite_ms},
                      {"gather_ms", f.gather_ms},
                      {"pack_ms", f.pack_ms},
                      {"bytes_sent", f.bytes_sent}};
  if (mode == Distribute::sort_last) {
    j["faces"] = f.faces;
    j["won_pixels"] = f.won_pixels;
    j["modeled_clocks"] = f.modeled_clocks;
  } else {
    j["band_first_row"] = f.band_first;
    j["band_tile_rows"] = f.band_rows;
  }
  return j;
}

int run(MpiSession& mpi, const DistributedRender& job) {
  const int rank = mpi.rank, n = mpi.size;
  // Every rank reads the scene file, or (--read-scene rank-0) only rank 0, which sends the others their
  // shares below.
  Scene scene;
  mpi.step([&] {
    if (rank == 0 && job.check_destinations) job.check_destinations();
    if (rank == 0 || !job.scatter_scene) scene = job.load_scene();
  });
  std::unique_ptr<Device> device;
  mpi.step([&] { device = open_device(job.device); });

  const bool sort_last = job.mode == Distribute::sort_last;
  if (n > 65535 && sort_last) throw UsageError("sort-last takes at most 65535 ranks");

  // sort-last: rank 0 plans the faces' ranks; every rank keeps only its share.
  std::vector<std::uint16_t> owner;
  std::vector<std::uint32_t> global_face;
  double plan_ms = 0;
  Scene share;
  std::unique_ptr<Scene> full;  // rank 0's whole scene for the error figures
  std::uint64_t faces = scene.triangle_count();
  if (sort_last && job.scatter_scene) {
    // Rank 0 plans, cuts every rank's share and scatters them (MPI_Scatterv); the others never hold more.
    std::vector<std::vector<char>> parts;
    mpi.step([&] {
      if (rank != 0) return;
      owner = assign_faces(scene, job, n, &plan_ms);
      for (int r = 0; r < n; ++r) parts.push_back(scene_to_bytes(share_of(scene, owner, r, global_face), global_face));
      check_scatter_size(parts);
    });
    const std::vector<char> bytes = scatter_parts(mpi, parts);
    parts = {};
    mpi.step([&] {
      share = scene_from_bytes(bytes, global_face);
      if (rank == 0 && !job.no_error) full = std::make_unique<Scene>(std::move(scene));
      scene = Scene{};
      owner = {};
    });
  } else if (job.scatter_scene) {
    // sort-first: every rank needs the whole scene; rank 0 broadcasts it.
    std::vector<char> bytes;
    std::uint64_t size = 0;
    mpi.step([&] {
      if (rank != 0) return;
      bytes = scene_to_bytes(scene, {});
      size = bytes.size();
    });
    MPI_Bcast(&size, 1, MPI_UINT64_T, 0, mpi.comm);
    bytes.resize(size);
    for (std::uint64_t first = 0; first < size; first += std::uint64_t(1) << 30)
      MPI_Bcast(bytes.data() + first, int(std::min<std::uint64_t>(size - first, std::uint64_t(1) << 30)), MPI_CHAR, 0,
                mpi.comm);
    mpi.step([&] {
      std::vector<std::uint32_t> none;
      if (rank != 0) scene = scene_from_bytes(bytes, none);
    });
  } else if (sort_last) {
    mpi.step([&] {
      if (rank == 0) owner = assign_faces(scene, job, n, &plan_ms);
    });
    owner.resize(faces);
    for (std::size_t first = 0; first < faces; first += std::size_t(1) << 30) {
      const int count = int(std::min<std::uint64_t>(faces - first, std::uint64_t(1) << 30));
      MPI_Bcast(owner.data() + first, count, MPI_UINT16_T, 0, mpi.comm);
    }
    mpi.step([&] {
      share = share_of(scene, owner, rank, global_face);
      if (rank == 0 && !job.no_error) full = std::make_unique<Scene>(std::move(scene));
      scene = Scene{};
      owner = {};
      owner.shrink_to_fit();
    });
  }

  const Scene& drawn = sort_last ? share : scene;  // what this rank renders
  const int W = drawn.width, H = drawn.height;
  const std::size_t pixels = std::size_t(W) * H;
  const bool float_output = job.options.float_output;

  const int pixel_bytes = float_output ? kFloatPixelBytes : int(sizeof(KeyPixel));
  MPI_Datatype pixel_type;
  MPI_Type_contiguous(pixel_bytes, MPI_BYTE, &pixel_type);
  MPI_Type_commit(&pixel_type);
  MPI_Op min_op;
  MPI_Op_create(min_key_for(pixel_bytes), 1, &min_op);
  const std::size_t block = (pixels + n - 1) / n;
  const CompositeBlocks blocks{block, pixel_bytes, pixel_type, mpi.comm, rank, n};
  // Pixels of pixel_bytes each: what a rank sends (every block), what it receives (every rank's copy of
  // its block), and rank 0's composited frame.
  std::vector<char> send, received(sort_last ? block * n * pixel_bytes : 0), all;

  RenderOptions options = job.options;
  if (sort_last && !options.plan) options.plan = PlanOptions{};  // the depth keys: a planned frame
  std::unique_ptr<Renderer> renderer;
  std::pair<int, int> band{0, 0};
  const int tile_rows = (H + options.tile_size - 1) / options.tile_size;
  std::vector<double> speed(n, 0.0);
  RenderedImage image;
  image.width = W;
  image.height = H;
  std::vector<std::vector<RankFigures>> frames;  // per timed frame, rank 0: every rank's
  std::vector<double> frame_ms;                  // rank 0: the whole distributed frame
  std::vector<FrameTimings> rank_timings;
  FrameStats last_stats;

  for (int i = 0; i < job.warmup + job.frames; ++i) {
    RankFigures fig;
    MPI_Barrier(mpi.comm);
    const double t_frame = now_ms();
    const Frame* frame = nullptr;
    std::vector<std::uint8_t> band_rgba;
    if (!sort_last) {
      const std::vector<std::pair<int, int>> all_bands = bands(tile_rows, speed);
      fig.band_first = all_bands[rank].first;
      fig.band_rows = all_bands[rank].second;
      // A step on every rank every frame (a step is collective); where the band moved, the renderer moves
      // it (a new renderer would allocate and map its buffers again: ~4 ms a frame here).
      mpi.step([&] {
        if (renderer && all_bands[rank] == band) return;
        band = all_bands[rank];
        if (band.second == 0) {
          renderer.reset();
        } else if (renderer) {
          renderer->set_band(band.first, band.second);
        } else {
          RenderOptions o = options;
          o.band_first = band.first;
          o.band_rows = band.second;
          renderer = std::make_unique<Renderer>(*device, o);
        }
      });
    } else if (!renderer) {
      mpi.step([&] { renderer = std::make_unique<Renderer>(*device, options); });
    }
    std::vector<std::uint64_t> keys;
    mpi.step([&] {
      if (!renderer) return;
      frame = &renderer->render(drawn);
      if (sort_last) keys = renderer->plan_keys(share);
    });
    if (frame) {
      fig.records = double(frame->stats.geometry.triangles_out);
      fig.record_bytes = double(record_bytes(options, frame->stats.geometry.triangles_out));
      fig.prepare_ms = prepare_of(frame->timings);
      fig.render_ms = frame->timings.unit_pass_ms + frame->timings.kernel_ms + frame->timings.readback_ms;
      fig.modeled_clocks = double(frame->stats.clocks.clocks);
      last_stats = frame->stats;
      rank_timings.push_back(frame->timings);
    }
    fig.frame_ms = now_ms() - t_frame;
    double t_comp = now_ms();
    if (sort_last) {
      // This rank's keys with the scene face in place of its own record index, its colours, its rank.
      send.assign(block * n * pixel_bytes, 0);
      const std::vector<std::uint32_t>& face = renderer->geometry().face;
      const std::uint8_t* rgba = frame->image.rgba.data();
      const float* rgb = float_output ? frame->image.rgb_float.data() : nullptr;
      std::size_t covered = 0;
      for (std::size_t p = 0; p < block * n; ++p) {
        KeyPixel px{PLAN_NO_KEY, 0, std::uint32_t(rank)};
        char* out = send.data() + p * pixel_bytes;
        if (p < pixels) {
          if (keys[p] != PLAN_NO_KEY) {
            px.key = (keys[p] & 0xFFFFFFFF00000000ull) | global_face[face[std::uint32_t(keys[p])]];
            ++covered;
          }
          std::memcpy(&px.rgba, rgba + 4 * p, 4);
          if (rgb) std::memcpy(out + sizeof px, rgb + 3 * p, 3 * sizeof(float));
        }
        std::memcpy(out, &px, sizeof px);
      }
      fig.faces = double(global_face.size());
      fig.pixels = double(covered);
      fig.pack_ms = now_ms() - t_comp;
      // The composite's own time: from the last rank's arrival (a rank that waits for a slower one is
      // imbalance, not compositing).
      MPI_Barrier(mpi.comm);
      t_comp = now_ms();
      // The reduce-scatter (composite.hpp), then this rank's composited block to rank 0.
      exchange_blocks(blocks, send, received);
      reduce_received(blocks, received, min_op);
      const char* mine = blocks.own(received);
      if (rank == 0) all.resize(block * n * pixel_bytes);
      const double t_gather = now_ms();
      MPI_Gather(mine, int(block), pixel_type, all.data(), int(block), pixel_type, 0, mpi.comm);
      fig.gather_ms = now_ms() - t_gather;
      // At least what leaves the rank: the other ranks' blocks of its keys, and its block to rank 0.
      fig.bytes_sent = double(pixel_bytes) * block * ((n - 1) + (rank == 0 ? 0 : 1));
    } else {
      const std::size_t pitch = std::size_t(W) * 4;
      const int y0 = std::min(H, band.first * options.tile_size);
      const int y1 = std::min(H, (band.first + band.second) * options.tile_size);
      fig.pixels = double(y1 - y0) * W;
      MPI_Barrier(mpi.comm);
      t_comp = now_ms();
      std::vector<int> counts(n), displs(n);
      const int mine_bytes = int(std::size_t(y1 - y0) * pitch);
      MPI_Allgather(&mine_bytes, 1, MPI_INT, counts.data(), 1, MPI_INT, mpi.comm);
      const int mine_first = int(std::size_t(y0) * pitch);
      MPI_Allgather(&mine_first, 1, MPI_INT, displs.data(), 1, MPI_INT, mpi.comm);
      if (rank == 0) image.rgba.assign(pixels * 4, 0);
      const std::uint8_t* src = frame ? frame->image.rgba.data() + mine_first : nullptr;
      MPI_Gatherv(src, mine_bytes, MPI_BYTE, image.rgba.data(), counts.data(), displs.data(), MPI_BYTE, 0, mpi.comm);
      fig.bytes_sent = rank == 0 ? 0 : mine_bytes;
      if (float_output) {  // the band's unclamped RGB too: 3 floats a pixel where rgba has 4 bytes
        for (int r = 0; r < n; ++r) counts[r] *= 3, displs[r] *= 3;
        if (rank == 0) image.rgb_float.assign(pixels * 3, 0.0f);
        const char* fsrc = frame ? reinterpret_cast<const char*>(frame->image.rgb_float.data()) + 3 * std::size_t(mine_first) : nullptr;
        MPI_Gatherv(fsrc, 3 * mine_bytes, MPI_BYTE, image.rgb_float.data(), counts.data(), displs.data(), MPI_BYTE, 0,
                    mpi.comm);
        fig.bytes_sent += rank == 0 ? 0 : 3.0 * mine_bytes;
      }
      // The next frame's bands: rows per ms of the shading kernel (the host stages are the whole frame's).
      const double my_speed = frame && frame->timings.kernel_ms > 0 ? band.second / frame->timings.kernel_ms : 0;
      std::vector<double> got(n);
      MPI_Allgather(&my_speed, 1, MPI_DOUBLE, got.data(), 1, MPI_DOUBLE, mpi.comm);
      for (int r = 0; r < n; ++r)
        if (got[r] > 0) speed[r] = got[r];
    }
    fig.composite_ms = now_ms() - t_comp;
    if (!sort_last) fig.gather_ms = fig.composite_ms;  // sort-first's composite is its gather
    MPI_Barrier(mpi.comm);
    const double whole = now_ms() - t_frame;
    std::vector<RankFigures> gathered(rank == 0 ? n : 0);
    MPI_Gather(&fig, kFigures, MPI_DOUBLE, gathered.data(), kFigures, MPI_DOUBLE, 0, mpi.comm);
    if (sort_last && rank == 0) {
      for (auto& g : gathered) g.won_pixels = 0;
      for (std::size_t p = 0; p < pixels; ++p) {
        const KeyPixel k = key_pixel(all, p, pixel_bytes);
        if (k.key != PLAN_NO_KEY) gathered[k.rank].won_pixels += 1;
      }
    }
    if (i >= job.warmup && rank == 0) {
      frames.push_back(gathered);
      frame_ms.push_back(whole);
    }
  }
  MPI_Op_free(&min_op);
  MPI_Type_free(&pixel_type);

  if (sort_last && rank == 0) {
    image.rgba.resize(pixels * 4);
    if (float_output) image.rgb_float.resize(pixels * 3);
    for (std::size_t p = 0; p < pixels; ++p) {
      const KeyPixel k = key_pixel(all, p, pixel_bytes);
      std::memcpy(&image.rgba[4 * p], &k.rgba, 4);
      if (float_output) std::memcpy(&image.rgb_float[3 * p], all.data() + p * pixel_bytes + sizeof k, 3 * sizeof(float));
    }
  }
  double peak = peak_rss_mb();
  std::vector<double> peaks(rank == 0 ? n : 0);
  MPI_Gather(&peak, 1, MPI_DOUBLE, peaks.data(), 1, MPI_DOUBLE, 0, mpi.comm);

  // Rank 0 writes the image and the report; the others wait for its word.
  mpi.step([&] {
    if (rank != 0) return;
    nlohmann::json errors = nlohmann::json::object();
    std::vector<std::string> lines;
    if (!job.no_error && job.error_figures) errors = job.error_figures(sort_last ? *full : scene, image, lines);
    // Per rank: the median over the timed frames of each figure.
    auto med = [&](int r, double RankFigures::*field) {
      std::vector<double> v;
      for (const auto& f : frames) v.push_back(f[r].*field);
      return median(v);
    };
    nlohmann::json per_rank = nlohmann::json::array();
    std::vector<double> render(n), prepare(n), rankframe(n);
    for (int r = 0; r < n; ++r) {
      RankFigures m;
      for (double RankFigures::*field :
           {&RankFigures::faces, &RankFigures::records, &RankFigures::pixels, &RankFigures::won_pixels,
            &RankFigures::modeled_clocks, &RankFigures::prepare_ms, &RankFigures::render_ms, &RankFigures::frame_ms,
            &RankFigures::composite_ms, &RankFigures::bytes_sent, &RankFigures::band_first, &RankFigures::band_rows,
            &RankFigures::record_bytes, &RankFigures::pack_ms, &RankFigures::gather_ms})
        m.*field = med(r, field);
      if (!sort_last) {  // the last frame's band
        m.band_first = frames.back()[r].band_first;
        m.band_rows = frames.back()[r].band_rows;
      }
      render[r] = m.render_ms;
      prepare[r] = m.prepare_ms;
      rankframe[r] = m.frame_ms;
      nlohmann::json j = figures_json(m, r, job.mode);
      j["peak_rss_mb"] = peaks[r];
      j["frames"] = nlohmann::json::array();
      for (const auto& f : frames) j["frames"].push_back(frame_json(f[r]));
      per_rank.push_back(j);
    }
    auto imbalance = [&](const std::vector<double>& v) {
      const double mean = std::accumulate(v.begin(), v.end(), 0.0) / double(v.size());
      return mean > 0 ? *std::max_element(v.begin(), v.end()) / mean : 1.0;
    };
    const double frame_median = median(frame_ms);
    nlohmann::json report = {
        {"scene", drawn.name},
        {"scene_file", job.scene_file},
        {"image", job.output},
        {"distribute", distribute_name(job.mode)},
        {"ranks", n},
        {"threads_per_rank", mpi.threads_per_rank},
        {"device", to_json(device->info())},
        {"method", method_name(options.method)},
        {"width", W},
        {"height", H},
        {"tile_size", options.tile_size},
        {"faces", faces},
        {"frame_ms", frame_median},
        {"frame_ms_samples", frame_ms},
        {"read_scene", job.scatter_scene ? "rank-0" : "every-rank"},
        {"float_output", float_output},
        {"frame_ms_note", "median of " + std::to_string(job.frames) + " frames after " + std::to_string(job.warmup) +
                              " warm-up frame(s), rank 0's clock from a barrier before the frame to one after the "
                              "composite; a loaded shared 2-core machine: compare ratios within one run"},
        {"timing", timing_json(frame_ms, job.warmup)},
        {"per_rank", per_rank},
        {"imbalance", {{"render_ms", imbalance(render)}, {"prepare_ms", imbalance(prepare)},
                       {"rank_frame_ms", imbalance(rankframe)}}},
        {"error", errors}};
    if (sort_last) {
      report["rank_partition"] = partition_name(job.rank_partition);
      report["planning_ms"] = plan_ms;
      report["composite"] = "MPI_Alltoall + MPI_Reduce_local (min of (depth, scene face) keys) + MPI_Gather to rank 0";
      std::vector<double> clocks(n);
      for (int r = 0; r < n; ++r) clocks[r] = per_rank[r]["modeled_clocks"].get<double>();
      report["imbalance"]["modeled_clocks"] = imbalance(clocks);
    } else {
      report["composite"] = "MPI_Gatherv of the bands to rank 0";
    }
    stamp_report(report, "render-distributed");
    write_image(job.output, image);
    if (!job.report.empty()) {
      try {
        write_text_atomically(job.report, report.dump(2) + "\n");
      } catch (...) {
        std::error_code ignored;
        std::filesystem::remove(job.output, ignored);
        throw;
      }
    }
    std::printf("%s: %dx%d, %llu faces, method %s, %s over %d ranks (%d threads each)\n",
                report["scene"].get<std::string>().c_str(), W, H, (unsigned long long)faces,
                method_name(options.method), distribute_name(job.mode), n, mpi.threads_per_rank);
    std::printf("frame: %.3f ms (median of %d after %d warm-up, barrier to barrier)\n", frame_median, job.frames,
                job.warmup);
    std::printf("rank  %s  records  pixels  prepare_ms  render_ms  composite_ms  bytes_sent  peak_rss_mb\n",
                sort_last ? "faces" : "band ");
    for (int r = 0; r < n; ++r) {
      const auto& j = per_rank[r];
      std::printf("%4d  %s  %7.0f  %6.0f  %10.3f  %9.3f  %12.3f  %10.0f  %11.1f\n", r,
                  sort_last ? std::to_string(j["faces"].get<long long>()).c_str()
                            : (std::to_string(j["band_first_row"].get<int>()) + "+" +
                               std::to_string(j["band_tile_rows"].get<int>()))
                                  .c_str(),
                  j["records"].get<double>(), j["pixels"].get<double>(), j["prepare_ms"].get<double>(),
                  j["render_ms"].get<double>(), j["composite_ms"].get<double>(), j["bytes_sent"].get<double>(),
                  j["peak_rss_mb"].get<double>());
    }
    std::printf("imbalance (max/mean): render %.3f, prepare %.3f\n", report["imbalance"]["render_ms"].get<double>(),
                report["imbalance"]["prepare_ms"].get<double>());
    for (const auto& l : lines) std::printf("%s\n", l.c_str());
    std::printf("wrote %s%s%s\n", job.output.c_str(), job.report.empty() ? "" : " and ", job.report.c_str());
    std::fflush(stdout);
  });
  return 0;
}

}  // namespace
}  // namespace distributed

bool mpi_built() { return true; }

namespace {

class MpiRankGroup : public RankGroup {
 public:
  int rank() const override { return mpi_.rank; }
  int size() const override { return mpi_.size; }
  void step(const std::function<void()>& f) override {
    try {
      mpi_.step(f);
    } catch (const distributed::RanksStopped& s) {
      throw StoppedRanks(s.code);
    }
  }
  std::vector<std::string> gather(const std::string& mine) override {
    const int n = mpi_.size, bytes = int(mine.size());
    std::vector<int> counts(mpi_.rank == 0 ? n : 0), displs(counts.size());
    MPI_Gather(&bytes, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, mpi_.comm);
    std::size_t total = 0;
    for (int r = 0; r < int(counts.size()); ++r) displs[r] = int(total), total += std::size_t(counts[r]);
    std::vector<char> all(total);
    MPI_Gatherv(mine.data(), bytes, MPI_CHAR, all.data(), counts.data(), displs.data(), MPI_CHAR, 0, mpi_.comm);
    std::vector<std::string> out;
    for (int r = 0; r < int(counts.size()); ++r) out.emplace_back(all.data() + displs[r], std::size_t(counts[r]));
    return out;
  }

 private:
  distributed::MpiSession mpi_;
};

}  // namespace

std::unique_ptr<RankGroup> RankGroup::join() { return std::make_unique<MpiRankGroup>(); }

int run_distributed_render(const DistributedRender& job) {
  distributed::MpiSession mpi;
  try {
    return distributed::run(mpi, job);
  } catch (const distributed::RanksStopped& s) {
    return s.code;
  } catch (const std::exception& e) {
    // Outside a step (a usage error every rank sees alike, or a bug): stop every rank now.
    const int code = [&] {
      if (const auto* err = dynamic_cast<const Error*>(&e)) return int(err->code());
      return int(ExitCode::internal);
    }();
    std::cerr << "parashade: error: rank " << mpi.rank << " of " << mpi.size << ": " << e.what() << "\n";
    MPI_Abort(mpi.comm, code);
    return code;
  }
}

}  // namespace parashade
