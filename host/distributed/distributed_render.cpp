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
#include "parashade/command_files.hpp"
#include "parashade/device.hpp"
#include "parashade/distributed.hpp"
#include "parashade/errors.hpp"
#include "parashade/frame_pipeline.hpp"
#include "parashade/notes.hpp"
#include "parashade/report.hpp"
#include "parashade/render_outputs.hpp"
#include "parashade/render_step.hpp"
#include "parashade/scene_files.hpp"
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

constexpr int kFigures = sizeof(RankFigures) / sizeof(double);

double peak_rss_mib() {
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
  FrameConfig c = job.request.options;
  c.plan.reset();
  c.band_first = 0;
  c.band_rows = -1;
  FramePipeline pipeline(c);
  const PreparedFrame& f = pipeline.prepare_frame(scene);
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
  mpi.collective([&] { MPI_Scatter(counts.data(), 1, MPI_INT, &mine, 1, MPI_INT, 0, mpi.comm); });
  std::vector<char> out(static_cast<std::size_t>(mine));
  mpi.collective([&] {
    MPI_Scatterv(all.data(), counts.data(), displs.data(), MPI_CHAR, out.data(), mine, MPI_CHAR, 0, mpi.comm);
  });
  return out;
}

// One rank's part of a distributed frame: the scene or its share, the frames, the composite, and on rank 0
// the result, its error figures and the outputs.
class RankRun {
 public:
  RankRun(MpiSession& mpi, const DistributedRender& job)
      : mpi_(mpi), job_(job), rank_(mpi.rank), n_(mpi.size), sort_last_(job.mode == Distribute::sort_last),
        options_(job.request.options) {
    if (sort_last_ && !options_.plan) options_.plan = PlanOptions{};  // the depth keys: a planned frame
  }

  int run(RenderResult* result, std::vector<std::string>* lines) {
    read_scene();
    mpi_.step([&] { device_ = open_device(job_.request.device); });
    if (rank_ == 0 && !job_.quiet && takes_default_device(job_.request.device))
      print_note(default_device_note(device_->info()));  // rank 0's: each rank takes its host's own
    if (n_ > 65535 && sort_last_) throw UsageError("sort-last takes at most 65535 ranks");
    share_scene();
    start_composite();
    for (int i = 0; i < job_.request.warmup + job_.request.frames; ++i) frame(i >= job_.request.warmup);
    MPI_Op_free(&min_op_);
    MPI_Type_free(&pixel_type_);
    if (sort_last_ && rank_ == 0) unpack_composite();
    double peak = peak_rss_mib();
    figures_.peak_rss_mib.resize(rank_ == 0 ? n_ : 0);
    mpi_.collective([&] {
      MPI_Gather(&peak, 1, MPI_DOUBLE, figures_.peak_rss_mib.data(), 1, MPI_DOUBLE, 0, mpi_.comm);
    });
    // Rank 0 writes the outputs; the others wait for its word.
    mpi_.step([&] {
      if (rank_ == 0) finish(result, lines);
    });
    return 0;
  }

 private:
  // Every rank reads the scene file, or (--read-scene rank-0) only rank 0; rank 0 checks the outputs first.
  void read_scene() {
    mpi_.step([&] {
      std::vector<std::filesystem::path> inputs;
      CommandFiles files;
      if (rank_ == 0) {
        job_.outputs.declare(files);
        files.check_folders();  // before the scene, whose loading may take many seconds
      }
      if (rank_ != 0 && job_.scatter_scene) return;
      scene_ = load_scene(job_.request.scene_file, inputs, job_.request.size);
      if (rank_ != 0) return;
      files.scene(inputs);
      files.check();
      warnings_ = scene_.warnings;
    });
    faces_ = scene_.triangle_count();
  }

  // sort-last: rank 0 plans the faces' ranks, every rank keeps only its share; sort-first with
  // --read-scene rank-0: rank 0 broadcasts the scene.
  void share_scene() {
    if (sort_last_ && job_.scatter_scene) scatter_shares();
    else if (job_.scatter_scene) broadcast_scene();
    else if (sort_last_) broadcast_owners();
  }

  // Rank 0 plans, cuts every rank's share and scatters them (MPI_Scatterv); the others never hold more.
  void scatter_shares() {
    std::vector<std::vector<char>> parts;
    std::vector<std::uint16_t> owner;
    mpi_.step([&] {
      if (rank_ != 0) return;
      owner = assign_faces(scene_, job_, n_, &plan_ms_);
      for (int r = 0; r < n_; ++r) parts.push_back(scene_to_bytes(share_of(scene_, owner, r, global_face_), global_face_));
      check_scatter_size(parts);
    });
    const std::vector<char> bytes = scatter_parts(mpi_, parts);
    parts = {};
    mpi_.step([&] {
      share_ = scene_from_bytes(bytes, global_face_);
      keep_full_scene();
    });
  }

  void broadcast_scene() {
    std::vector<char> bytes;
    std::uint64_t size = 0;
    mpi_.step([&] {
      if (rank_ != 0) return;
      bytes = scene_to_bytes(scene_, {});
      size = bytes.size();
    });
    mpi_.collective([&] { MPI_Bcast(&size, 1, MPI_UINT64_T, 0, mpi_.comm); });
    bytes.resize(size);
    for (std::uint64_t first = 0; first < size; first += std::uint64_t(1) << 30)
      mpi_.collective([&] {
        MPI_Bcast(bytes.data() + first, int(std::min<std::uint64_t>(size - first, std::uint64_t(1) << 30)), MPI_CHAR, 0,
            mpi_.comm);
      });
    mpi_.step([&] {
      std::vector<std::uint32_t> none;
      if (rank_ != 0) scene_ = scene_from_bytes(bytes, none);
    });
    faces_ = scene_.triangle_count();
  }

  void broadcast_owners() {
    std::vector<std::uint16_t> owner;
    mpi_.step([&] {
      if (rank_ == 0) owner = assign_faces(scene_, job_, n_, &plan_ms_);
    });
    owner.resize(faces_);
    for (std::size_t first = 0; first < faces_; first += std::size_t(1) << 30) {
      const int count = int(std::min<std::uint64_t>(faces_ - first, std::uint64_t(1) << 30));
      mpi_.collective([&] { MPI_Bcast(owner.data() + first, count, MPI_UINT16_T, 0, mpi_.comm); });
    }
    mpi_.step([&] {
      share_ = share_of(scene_, owner, rank_, global_face_);
      keep_full_scene();
    });
  }

  // Rank 0 keeps the whole scene for the error figures; the others drop it.
  void keep_full_scene() {
    if (rank_ == 0 && job_.request.error_figures) full_ = std::make_unique<Scene>(std::move(scene_));
    scene_ = Scene{};
  }

  const Scene& drawn() const { return sort_last_ ? share_ : scene_; }

  void start_composite() {
    const std::size_t pixels = std::size_t(drawn().width) * drawn().height;
    pixel_bytes_ = options_.float_output ? kFloatPixelBytes : int(sizeof(KeyPixel));
    MPI_Type_contiguous(pixel_bytes_, MPI_BYTE, &pixel_type_);
    MPI_Type_commit(&pixel_type_);
    MPI_Op_create(min_key_for(pixel_bytes_), 1, &min_op_);
    block_ = (pixels + n_ - 1) / n_;
    if (sort_last_) received_.resize(block_ * n_ * pixel_bytes_);
    speed_.assign(n_, 0.0);
    image_.width = drawn().width;
    image_.height = drawn().height;
  }

  // sort-first: this rank's band by the ranks' measured speed; the renderer moves its band where it moved
  // (a new renderer would allocate and map its buffers again: ~4 ms a frame here). A step on every rank
  // every frame (a step is collective).
  void place_band(RankFigures& fig) {
    const int tile_rows = (drawn().height + options_.tile_size - 1) / options_.tile_size;
    const std::vector<std::pair<int, int>> all = bands(tile_rows, speed_);
    fig.band_first = all[rank_].first;
    fig.band_rows = all[rank_].second;
    mpi_.step([&] {
      if (renderer_ && all[rank_] == band_) return;
      band_ = all[rank_];
      if (band_.second == 0) {
        renderer_.reset();
      } else if (renderer_) {
        renderer_->set_band(band_.first, band_.second);
      } else {
        RenderOptions o = options_;
        o.band_first = band_.first;
        o.band_rows = band_.second;
        renderer_ = std::make_unique<Renderer>(*device_, o);
      }
    });
  }

  // One frame of every rank; rank 0 keeps the timed ones' figures.
  void frame(bool timed) {
    RankFigures fig;
    mpi_.collective([&] { MPI_Barrier(mpi_.comm); });
    const double t_frame = now_ms();
    if (!sort_last_) place_band(fig);
    else if (!renderer_) mpi_.step([&] { renderer_ = std::make_unique<Renderer>(*device_, options_); });
    const Frame* frame = nullptr;
    std::vector<std::uint64_t> keys;
    mpi_.step([&] {
      if (!renderer_) return;
      frame = &renderer_->render(drawn());
      if (sort_last_) keys = renderer_->plan_keys(share_);
    });
    if (frame) measured(*frame, fig);
    fig.frame_ms = now_ms() - t_frame;
    const double t_comp = sort_last_ ? composite_keys(*frame, keys, fig) : gather_band(frame, fig);
    fig.composite_ms = now_ms() - t_comp;
    if (!sort_last_) fig.gather_ms = fig.composite_ms;  // sort-first's composite is its gather
    mpi_.collective([&] { MPI_Barrier(mpi_.comm); });
    const double whole = now_ms() - t_frame;
    std::vector<RankFigures> gathered(rank_ == 0 ? n_ : 0);
    mpi_.collective([&] {
      MPI_Gather(&fig, kFigures, MPI_DOUBLE, gathered.data(), kFigures, MPI_DOUBLE, 0, mpi_.comm);
    });
    if (sort_last_ && rank_ == 0) count_won_pixels(gathered);
    if (timed && rank_ == 0) {
      figures_.frames.push_back(gathered);
      frame_ms_.push_back(whole);
    }
  }

  void measured(const Frame& frame, RankFigures& fig) {
    fig.records = double(frame.stats.geometry.triangles_out);
    fig.record_bytes = double(record_bytes(options_, frame.stats.geometry.triangles_out));
    fig.prepare_ms = prepare_of(frame.timings);
    fig.render_ms = frame.timings.unit_pass_ms + frame.timings.kernel_ms + frame.timings.readback_ms;
    fig.modeled_clocks = double(frame.stats.clocks.clocks);
    last_stats_ = frame.stats;
  }

  // sort-last: this rank's keys with the scene face in place of its own record index, its colours, its
  // rank, reduce-scattered (composite.hpp) and gathered to rank 0. Returns the composite's start: from the
  // last rank's arrival (a rank that waits for a slower one is imbalance, not compositing).
  double composite_keys(const Frame& frame, const std::vector<std::uint64_t>& keys, RankFigures& fig) {
    const double t_pack = now_ms();
    const std::size_t pixels = std::size_t(drawn().width) * drawn().height;
    send_.assign(block_ * n_ * pixel_bytes_, 0);
    const std::vector<std::uint32_t>& face = renderer_->geometry().face;
    const std::uint8_t* rgba = frame.image.rgba.data();
    const float* rgb = options_.float_output ? frame.image.rgb_float.data() : nullptr;
    std::size_t covered = 0;
    for (std::size_t p = 0; p < block_ * n_; ++p) {
      KeyPixel px{PLAN_NO_KEY, 0, std::uint32_t(rank_)};
      char* out = send_.data() + p * pixel_bytes_;
      if (p < pixels) {
        if (keys[p] != PLAN_NO_KEY) {
          px.key = (keys[p] & 0xFFFFFFFF00000000ull) | global_face_[face[std::uint32_t(keys[p])]];
          ++covered;
        }
        std::memcpy(&px.rgba, rgba + 4 * p, 4);
        if (rgb) std::memcpy(out + sizeof px, rgb + 3 * p, 3 * sizeof(float));
      }
      std::memcpy(out, &px, sizeof px);
    }
    fig.faces = double(global_face_.size());
    fig.pixels = double(covered);
    fig.pack_ms = now_ms() - t_pack;
    mpi_.collective([&] { MPI_Barrier(mpi_.comm); });
    const double t_comp = now_ms();
    const CompositeBlocks blocks{block_, pixel_bytes_, pixel_type_, mpi_.comm, rank_, n_};
    mpi_.collective([&] { exchange_blocks(blocks, send_, received_); });
    reduce_received(blocks, received_, min_op_);
    const char* mine = blocks.own(received_);
    if (rank_ == 0) all_.resize(block_ * n_ * pixel_bytes_);
    const double t_gather = now_ms();
    mpi_.collective([&] {
      MPI_Gather(mine, int(block_), pixel_type_, all_.data(), int(block_), pixel_type_, 0, mpi_.comm);
    });
    fig.gather_ms = now_ms() - t_gather;
    // At least what leaves the rank: the other ranks' blocks of its keys, and its block to rank 0.
    fig.bytes_sent = double(pixel_bytes_) * block_ * ((n_ - 1) + (rank_ == 0 ? 0 : 1));
    return t_comp;
  }

  // sort-first: the bands gathered to rank 0 (MPI_Gatherv), then the next frame's speeds.
  double gather_band(const Frame* frame, RankFigures& fig) {
    const int W = drawn().width, H = drawn().height;
    const std::size_t pitch = std::size_t(W) * 4;
    const int y0 = std::min(H, band_.first * options_.tile_size);
    const int y1 = std::min(H, (band_.first + band_.second) * options_.tile_size);
    fig.pixels = double(y1 - y0) * W;
    mpi_.collective([&] { MPI_Barrier(mpi_.comm); });
    const double t_comp = now_ms();
    std::vector<int> counts(n_), displs(n_);
    const int mine_bytes = int(std::size_t(y1 - y0) * pitch);
    mpi_.collective([&] { MPI_Allgather(&mine_bytes, 1, MPI_INT, counts.data(), 1, MPI_INT, mpi_.comm); });
    const int mine_first = int(std::size_t(y0) * pitch);
    mpi_.collective([&] { MPI_Allgather(&mine_first, 1, MPI_INT, displs.data(), 1, MPI_INT, mpi_.comm); });
    const std::size_t pixels = std::size_t(W) * H;
    if (rank_ == 0) image_.rgba.assign(pixels * 4, 0);
    const std::uint8_t* src = frame ? frame->image.rgba.data() + mine_first : nullptr;
    mpi_.collective([&] {
      MPI_Gatherv(src, mine_bytes, MPI_BYTE, image_.rgba.data(), counts.data(), displs.data(), MPI_BYTE, 0, mpi_.comm);
    });
    fig.bytes_sent = rank_ == 0 ? 0 : mine_bytes;
    if (options_.float_output) {  // the band's unclamped RGB too: 3 floats a pixel where rgba has 4 bytes
      for (int r = 0; r < n_; ++r) counts[r] *= 3, displs[r] *= 3;
      if (rank_ == 0) image_.rgb_float.assign(pixels * 3, 0.0f);
      const char* fsrc =
          frame ? reinterpret_cast<const char*>(frame->image.rgb_float.data()) + 3 * std::size_t(mine_first) : nullptr;
      mpi_.collective([&] {
        MPI_Gatherv(fsrc, 3 * mine_bytes, MPI_BYTE, image_.rgb_float.data(), counts.data(), displs.data(), MPI_BYTE, 0,
            mpi_.comm);
      });
      fig.bytes_sent += rank_ == 0 ? 0 : 3.0 * mine_bytes;
    }
    // The next frame's bands: rows per ms of the shading kernel (the host stages are the whole frame's).
    const double my_speed = frame && frame->timings.kernel_ms > 0 ? band_.second / frame->timings.kernel_ms : 0;
    std::vector<double> got(n_);
    mpi_.collective([&] { MPI_Allgather(&my_speed, 1, MPI_DOUBLE, got.data(), 1, MPI_DOUBLE, mpi_.comm); });
    for (int r = 0; r < n_; ++r)
      if (got[r] > 0) speed_[r] = got[r];
    return t_comp;
  }

  void count_won_pixels(std::vector<RankFigures>& gathered) const {
    const std::size_t pixels = std::size_t(drawn().width) * drawn().height;
    for (auto& g : gathered) g.won_pixels = 0;
    for (std::size_t p = 0; p < pixels; ++p) {
      const KeyPixel k = key_pixel(all_, p, pixel_bytes_);
      if (k.key != PLAN_NO_KEY) gathered[k.rank].won_pixels += 1;
    }
  }

  void unpack_composite() {
    const std::size_t pixels = std::size_t(drawn().width) * drawn().height;
    image_.rgba.resize(pixels * 4);
    if (options_.float_output) image_.rgb_float.resize(pixels * 3);
    for (std::size_t p = 0; p < pixels; ++p) {
      const KeyPixel k = key_pixel(all_, p, pixel_bytes_);
      std::memcpy(&image_.rgba[4 * p], &k.rgba, 4);
      if (options_.float_output)
        std::memcpy(&image_.rgb_float[3 * p], all_.data() + p * pixel_bytes_ + sizeof k, 3 * sizeof(float));
    }
  }

  // Rank 0: the composited frame's result, its error figures against the whole scene, the outputs.
  void finish(RenderResult* result, std::vector<std::string>* lines) {
    auto figures = std::make_shared<DistributedFigures>(std::move(figures_));
    figures->mode = job_.mode;
    figures->ranks = n_;
    figures->threads_per_rank = mpi_.threads_per_rank;
    figures->faces = faces_;
    figures->scatter_scene = job_.scatter_scene;
    figures->rank_partition = job_.rank_partition;
    figures->planning_ms = plan_ms_;
    RenderResult r;
    r.scene_name = drawn().name;
    r.scene_file = job_.request.scene_file;
    r.width = image_.width;
    r.height = image_.height;
    r.options = options_;
    r.mode = distribute_device_mode(job_.mode);
    r.devices = {device_->info()};
    r.frames = job_.request.frames;
    r.warmup = job_.request.warmup;
    r.image = std::move(image_);
    r.stats = last_stats_;
    r.frame_ms = frame_ms_;
    r.warnings = warnings_;
    r.distributed = std::move(figures);
    if (job_.request.error_figures)
      r.errors = error_figures(sort_last_ ? *full_ : scene_, options_, r.image, job_.outputs.needs_reference(), job_.request.flip);
    *lines = job_.outputs.write(r);
    *result = std::move(r);
  }

  MpiSession& mpi_;
  const DistributedRender& job_;
  const int rank_, n_;
  const bool sort_last_;
  RenderOptions options_;
  Scene scene_, share_;
  std::unique_ptr<Scene> full_;  // rank 0's whole scene for the error figures (sort-last)
  std::vector<std::string> warnings_;
  std::vector<std::uint32_t> global_face_;
  std::uint64_t faces_ = 0;
  double plan_ms_ = 0;
  std::unique_ptr<Device> device_;
  std::unique_ptr<Renderer> renderer_;
  std::pair<int, int> band_{0, 0};
  std::vector<double> speed_;
  int pixel_bytes_ = 0;
  std::size_t block_ = 0;
  MPI_Datatype pixel_type_;
  MPI_Op min_op_;
  // Pixels of pixel_bytes_ each: what a rank sends (every block), what it receives (every rank's copy of
  // its block), and rank 0's composited frame.
  std::vector<char> send_, received_, all_;
  RenderedImage image_;
  DistributedFigures figures_;   // rank 0: every rank's figures per timed frame
  std::vector<double> frame_ms_; // rank 0: the whole distributed frame
  FrameStats last_stats_;
};
}  // namespace
}  // namespace distributed

bool mpi_built() { return true; }

namespace {

class MpiRankGroup : public RankGroup {
 public:
  explicit MpiRankGroup(double rank_timeout) : mpi_(rank_timeout) {}
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
    mpi_.collective([&] { MPI_Gather(&bytes, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, mpi_.comm); });
    std::size_t total = 0;
    for (int r = 0; r < int(counts.size()); ++r) displs[r] = int(total), total += std::size_t(counts[r]);
    std::vector<char> all(total);
    mpi_.collective([&] {
      MPI_Gatherv(mine.data(), bytes, MPI_CHAR, all.data(), counts.data(), displs.data(), MPI_CHAR, 0, mpi_.comm);
    });
    std::vector<std::string> out;
    for (int r = 0; r < int(counts.size()); ++r) out.emplace_back(all.data() + displs[r], std::size_t(counts[r]));
    return out;
  }

 private:
  distributed::MpiSession mpi_;
};

}  // namespace

std::unique_ptr<RankGroup> RankGroup::join(double rank_timeout) { return std::make_unique<MpiRankGroup>(rank_timeout); }

int run_distributed_render(const DistributedRender& job, RenderResult* result, std::vector<std::string>* lines) {
  distributed::MpiSession mpi(job.rank_timeout);
  try {
    return distributed::RankRun(mpi, job).run(result, lines);
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
