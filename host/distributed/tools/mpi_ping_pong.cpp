// parashade_mpi_ping_pong: the α–β parameters of the distributed frame's cost model (docs/distributed.md).
// Rank 0 and rank 1 bounce messages of 8 B .. 32 MiB; one line of JSON per size with the median one-way
// time (half the round trip) over the repetitions, then the least-squares α (s) and β (s/byte); rank 0
// also times the sort-last compositing operator (min of 16-byte keys) per pixel, γ (s/pixel).
#include <mpi.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "../composite.hpp"

using parashade::distributed::KeyPixel;
using parashade::distributed::min_key_for;

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (size < 2) {
    if (rank == 0) std::fprintf(stderr, "parashade_mpi_ping_pong: run with mpirun -np 2\n");
    MPI_Finalize();
    return 2;
  }
  std::vector<double> xs, ys;
  std::vector<char> buf(std::size_t(32) << 20);
  if (rank == 0) std::printf("{\"ping_pong\": [\n");
  for (std::size_t bytes = 8; bytes <= buf.size(); bytes *= 4) {
    const int reps = bytes < (1 << 20) ? 200 : 10;
    std::vector<double> t;
    for (int r = 0; r < reps + 2; ++r) {
      MPI_Barrier(MPI_COMM_WORLD);
      const double t0 = MPI_Wtime();
      if (rank == 0) {
        MPI_Send(buf.data(), int(bytes), MPI_BYTE, 1, 0, MPI_COMM_WORLD);
        MPI_Recv(buf.data(), int(bytes), MPI_BYTE, 1, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      } else if (rank == 1) {
        MPI_Recv(buf.data(), int(bytes), MPI_BYTE, 0, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        MPI_Send(buf.data(), int(bytes), MPI_BYTE, 0, 0, MPI_COMM_WORLD);
      }
      if (r >= 2) t.push_back((MPI_Wtime() - t0) / 2);
    }
    std::sort(t.begin(), t.end());
    const double med = t[t.size() / 2];
    xs.push_back(double(bytes));
    ys.push_back(med);
    if (rank == 0)
      std::printf("  {\"bytes\": %zu, \"one_way_s\": %.9g}%s\n", bytes, med, bytes * 4 <= buf.size() ? "," : "");
  }
  // Least squares y = α + β x.
  const double n = double(xs.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < xs.size(); ++i) sx += xs[i], sy += ys[i], sxx += xs[i] * xs[i], sxy += xs[i] * ys[i];
  const double beta = (n * sxy - sx * sy) / (n * sxx - sx * sx), alpha = (sy - beta * sx) / n;
  // α alone from the smallest message (the fit's intercept is dominated by the large ones).
  const double alpha_small = ys.front();
  // γ: the compositing operator over 1M pixels, host only.
  const int pixels = 1 << 20;
  std::vector<KeyPixel> a(pixels), b(pixels);
  for (int i = 0; i < pixels; ++i) a[i] = {std::uint64_t(i * 2654435761u), 1, 0}, b[i] = {std::uint64_t(i * 40503u), 2, 1};
  MPI_Datatype type;
  MPI_Type_contiguous(16, MPI_BYTE, &type);
  MPI_Type_commit(&type);
  int len = pixels;
  std::vector<double> g;
  for (int r = 0; r < 7; ++r) {
    const double t0 = MPI_Wtime();
    min_key_for(16)(a.data(), b.data(), &len, &type);
    g.push_back((MPI_Wtime() - t0) / pixels);
  }
  std::sort(g.begin(), g.end());
  MPI_Type_free(&type);
  if (rank == 0)
    std::printf("], \"alpha_s\": %.9g, \"alpha_small_message_s\": %.9g, \"beta_s_per_byte\": %.9g, "
                "\"gamma_s_per_pixel\": %.9g, \"ranks\": %d}\n",
                alpha, alpha_small, beta, g[g.size() / 2], size);
  MPI_Finalize();
  return 0;
}
