// parashade_mpi_composite_probe: the sort-last composite taken apart (docs/distributed.md). On N ranks,
// with the frame's buffers (16 or 32 bytes a pixel, P pixels, blocks of P/N) and the frame's operator,
// it times each part on its own: MPI_Alltoall of the blocks (what a ring reduce-scatter moves), the
// operator applied with MPI_Reduce_local to the N−1 received copies of a rank's block, both together (the
// renderer's reduce-scatter), MPI_Reduce_scatter_block with the same operator (Open MPI's own, which the
// renderer used before: slower), and the MPI_Gather of the blocks to rank 0. It checks that both
// reduce-scatters give the same bytes.
//   mpirun -np N parashade_mpi_composite_probe [--pixels P] [--float] [--reps R]
// One JSON object on rank 0's stdout; each time is the slowest rank's, the median over R repetitions
// (after two untimed ones), in ms. The keys are random per pixel: the operator's worst case.
#include <mpi.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "../composite.hpp"

using parashade::distributed::CompositeBlocks;
using parashade::distributed::KeyPixel;
using parashade::distributed::kFloatPixelBytes;
using parashade::distributed::min_key_for;

namespace {

// The slowest rank's time of `body`, median over `reps` (two untimed runs first).
double timed_ms(int reps, const std::function<void()>& body) {
  std::vector<double> t;
  for (int r = 0; r < reps + 2; ++r) {
    MPI_Barrier(MPI_COMM_WORLD);
    const double t0 = MPI_Wtime();
    body();
    double mine = (MPI_Wtime() - t0) * 1e3, slowest = 0;
    MPI_Allreduce(&mine, &slowest, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    if (r >= 2) t.push_back(slowest);
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

// A rank's pixels as a frame leaves them: about two thirds covered, keys from a hash of (rank, pixel).
void fill(std::vector<char>& buf, std::size_t pixels, int bytes, int rank) {
  for (std::size_t p = 0; p < pixels; ++p) {
    std::uint64_t h = (p + 1) * 0x9E3779B97F4A7C15ull ^ (std::uint64_t(rank) + 1) * 0xC2B2AE3D27D4EB4Full;
    h ^= h >> 29;
    KeyPixel px{h % 3 ? h : ~std::uint64_t(0), std::uint32_t(h >> 7), std::uint32_t(rank)};
    std::memset(buf.data() + p * bytes, 0, std::size_t(bytes));
    std::memcpy(buf.data() + p * bytes, &px, sizeof px);
  }
}

int usage(int rank, const char* why) {
  if (rank == 0)
    std::fprintf(stderr, "parashade_mpi_composite_probe: %s\nusage: mpirun -np N parashade_mpi_composite_probe "
                 "[--pixels P] [--float] [--reps R]\n", why);
  MPI_Finalize();
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, n = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &n);
  long long pixels_arg = 1920LL * 1080;
  int bytes = int(sizeof(KeyPixel)), reps = 7;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--float") bytes = kFloatPixelBytes;
    else if ((a == "--pixels" || a == "--reps") && i + 1 < argc) {
      char* end = nullptr;
      const long long v = std::strtoll(argv[++i], &end, 10);
      if (*end || v < 1 || v > (1LL << 26)) return usage(rank, ("bad value for " + a).c_str());
      if (a == "--pixels") pixels_arg = v;
      else reps = int(v);
    } else return usage(rank, ("unknown argument '" + a + "'").c_str());
  }
  const std::size_t block = (std::size_t(pixels_arg) + n - 1) / n, all_pixels = block * n;
  MPI_Datatype type;
  MPI_Type_contiguous(bytes, MPI_BYTE, &type);
  MPI_Type_commit(&type);
  MPI_Op op;
  MPI_Op_create(min_key_for(bytes), 1, &op);

  std::vector<char> send(all_pixels * bytes), mine(block * bytes), received(all_pixels * bytes),
      gathered(rank == 0 ? all_pixels * bytes : 0);
  fill(send, all_pixels, bytes, rank);
  const CompositeBlocks blocks{block, bytes, type, MPI_COMM_WORLD, rank, n};
  const char* own = blocks.own(received);  // this rank's block, composited in place
  const auto reduce_local = [&] { parashade::distributed::reduce_received(blocks, received, op); };
  const auto alltoall = [&] { parashade::distributed::exchange_blocks(blocks, send, received); };

  const double alltoall_ms = timed_ms(reps, alltoall);
  // Again on the same received blocks: the operator is branchless, so a repetition costs the same.
  const double reduce_local_ms = timed_ms(reps, reduce_local);
  const double alltoall_reduce_local_ms = timed_ms(reps, [&] {
    alltoall();
    reduce_local();
  });
  const double reduce_scatter_block_ms = timed_ms(reps, [&] {
    MPI_Reduce_scatter_block(send.data(), mine.data(), int(block), type, op, MPI_COMM_WORLD);
  });
  int same = std::memcmp(own, mine.data(), block * bytes) == 0, all_same = 0;
  MPI_Allreduce(&same, &all_same, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  const double gather_ms = timed_ms(reps, [&] {
    MPI_Gather(own, int(block), type, gathered.data(), int(block), type, 0, MPI_COMM_WORLD);
  });
  // One rank's memory traffic floor: a plain copy of the whole send buffer.
  const double copy_ms = timed_ms(reps, [&] { std::memcpy(received.data(), send.data(), send.size()); });

  if (rank == 0)
    std::printf("{\"ranks\": %d, \"pixels\": %lld, \"pixel_bytes\": %d, \"reps\": %d, \"alltoall_ms\": %.4f, "
                "\"reduce_local_ms\": %.4f, \"alltoall_reduce_local_ms\": %.4f, \"reduce_scatter_block_ms\": %.4f, "
                "\"same_bytes\": %s, \"gather_ms\": %.4f, \"copy_send_buffer_ms\": %.4f}\n",
                n, pixels_arg, bytes, reps, alltoall_ms, reduce_local_ms, alltoall_reduce_local_ms,
                reduce_scatter_block_ms, all_same ? "true" : "false", gather_ms, copy_ms);
  MPI_Op_free(&op);
  MPI_Type_free(&type);
  MPI_Finalize();
  return all_same ? 0 : 1;
}
