#pragma once
// Warnings for objects that vanish from a frame without an error (issue 17, item 11): triangles the
// sierpinski unit's vertex snap made degenerate, and a frame that covers no pixel although triangles
// reached the screen.
#include <ostream>

#include "parashade/frame_stats.hpp"
#include "parashade/image.hpp"

namespace parashade {

void warn_vanishing(const FrameStats& stats, const RenderedImage& image, std::ostream& err);

}  // namespace parashade
