#pragma once
// `parashade render`'s arguments as a render request without rendering, for front ends that take render's
// options by their names (the Python module, docs/python.md): the command's own definition parses and
// checks them, so every name, default and message is the command's.
#include <functional>
#include <string>
#include <vector>

#include "parashade/render_outputs.hpp"
#include "parashade/render_step.hpp"

namespace parashade::cli {

struct RenderCall {
  RenderRequest request;
  RenderOutputs outputs;  // image empty: nothing is written
  // render's checks of the devices the request resolved to (--keep-going, pictures on a split frame),
  // then its notes on stderr (not with -q).
  std::function<void(const ResolvedRender&)> check_resolved;
};

// `words`: render's arguments after the command's name, the scene first ("scene.json", "--method", "phong").
// -o is optional; --report and the pictures need it. --distribute (MPI ranks) is refused. Throws UsageError
// with render's message (an unknown option with its nearest spelling), or the errors of its checks.
RenderCall parse_render_call(const std::vector<std::string>& words);

}  // namespace parashade::cli
