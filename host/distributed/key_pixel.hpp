// One pixel as the sort-last ranks composite it, and the composite's MPI operator (docs/distributed.md).
// Shared by the distributed frame and the composite probe (tools/), so the probe times the same operator.
#pragma once

#include <mpi.h>

#include <cstdint>
#include <cstring>

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

}  // namespace parashade::distributed
