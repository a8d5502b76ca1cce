// Every parashade command on one app (commands.hpp): the command line's and the Python module's.
#include "commands.hpp"

#include "../cl/build_notice.hpp"

namespace parashade::cli {

std::vector<Command> add_commands(CLI::App& app) {
  return {add_devices_command(app),     add_phong_study_command(app), add_render_command(app),
          add_plan_command(app),        add_tune_command(app),        add_scaling_command(app),
          add_unit_error_command(app),  add_combinations_command(app), add_vectors_command(app),
          add_compare_command(app)};
}

std::optional<int> run_parsed(const std::vector<Command>& commands, bool notices) {
  for (const Command& c : commands)
    if (c.app->parsed()) {
      const CLI::Option* quiet = c.app->get_option_no_throw("--quiet");
      set_kernel_build_notices(notices && !(quiet && quiet->count() > 0));
      return c.run();
    }
  return std::nullopt;
}

}  // namespace parashade::cli
