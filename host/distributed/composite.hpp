// The sort-last composite (docs/distributed.md): one pixel as the ranks composite it, the MPI operator, and
// the reduce-scatter in its two steps. Shared by the distributed frame and the composite probe (tools/), so
// the probe times the frame's own code.
#pragma once

#include <mpi.h>

#include <cstdint>
#include <cstring>
#include <vector>

namespace parashade::distributed {

// The least key (depth, scene face) wins; its colour and rank go with it. 16 bytes; with --float the
// pixel's unclamped RGB follows (3 floats and 4 bytes of padding: 32 bytes a pixel), so the float image is
// the winner's too.
struct KeyPixel {
  std::uint64_t key;
  std::uint32_t rgba;
  std::uint32_t rank;
};
static_assert(sizeof(KeyPixel) == 16, "KeyPixel is sent as 16 bytes");
constexpr int kFloatPixelBytes = 32;

// The operator on pixels of BYTES bytes: the least key wins, equal keys (no rank covers the pixel) go to
// the lowest rank. The size is a template parameter so each copy is a fixed-size move, and the winner is
// chosen by a select, not a branch (which pixel wins is close to random where small triangles meet).
template <int BYTES>
void min_key(void* in, void* inout, int* len, MPI_Datatype*) {
  const char* a = static_cast<const char*>(in);
  char* b = static_cast<char*>(inout);
  for (int i = 0; i < *len; ++i, a += BYTES, b += BYTES) {
    KeyPixel x, y;
    std::memcpy(&x, a, sizeof x);
    std::memcpy(&y, b, sizeof y);
    const bool take = x.key < y.key || (x.key == y.key && x.rank < y.rank);
    char winner[BYTES];
    std::memcpy(winner, take ? a : b, BYTES);
    std::memcpy(b, winner, BYTES);
  }
}

// The operator for pixels of `bytes` bytes (16, or kFloatPixelBytes with --float).
inline MPI_User_function* min_key_for(int bytes) {
  return bytes == kFloatPixelBytes ? &min_key<kFloatPixelBytes> : &min_key<int(sizeof(KeyPixel))>;
}

// Pixels of one composite: `block` pixels of `bytes` bytes per rank, N blocks in `send` and `received`.
struct CompositeBlocks {
  std::size_t block;
  int bytes;
  MPI_Datatype type;  // `bytes` contiguous bytes
  MPI_Comm comm;
  int rank, ranks;
  char* own(std::vector<char>& received) const { return received.data() + std::size_t(rank) * block * bytes; }
};

// Step 1 of the reduce-scatter: each rank gets every rank's copy of its block (MPI_Alltoall: the bytes a ring
// reduce-scatter moves).
inline void exchange_blocks(const CompositeBlocks& c, const std::vector<char>& send, std::vector<char>& received) {
  MPI_Alltoall(send.data(), int(c.block), c.type, received.data(), int(c.block), c.type, c.comm);
}

// Step 2: the operator applied to the other ranks' copies into this rank's own (MPI_Reduce_local). The
// operator is a minimum over (key, rank), so the order does not matter. Together the two steps are 3-4x
// faster here than Open MPI's MPI_Reduce_scatter_block with the same operator (the composite probe).
inline void reduce_received(const CompositeBlocks& c, std::vector<char>& received, MPI_Op op) {
  char* own = c.own(received);
  for (int r = 0; r < c.ranks; ++r)
    if (r != c.rank) MPI_Reduce_local(received.data() + std::size_t(r) * c.block * c.bytes, own, int(c.block), c.type, op);
}

}  // namespace parashade::distributed
