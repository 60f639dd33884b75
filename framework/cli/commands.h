// The `maquette` subcommands; each file cmd_<name>.cpp adds one to the program.
#pragma once

#include <CLI/CLI.hpp>

namespace maquette {
struct PanoramaJob;  // render/render_job.h
}

namespace maquette::cli {

void add_cells_command(CLI::App& app);
void add_info_command(CLI::App& app);
void add_modules_command(CLI::App& app);
void add_run_command(CLI::App& app);
void add_export_command(CLI::App& app);
void add_demo_command(CLI::App& app);
void add_ingest_command(CLI::App& app);
void add_view_command(CLI::App& app);
void add_render_command(CLI::App& app);
// `render fit`, under the `render` command.
void add_render_fit_command(CLI::App* render);

// -t,--threads into `threads`: worker threads, 0 for all cores (at most 1024).
void add_threads_option(CLI::App* cmd, int& threads);

// A panorama's light and air, into `job` (which must outlive the command): --haze-distance,
// --sun AZIMUTH ALTITUDE and --shadows (`render panorama`, and `render fit --panorama`).
void add_panorama_look_options(CLI::App* cmd, PanoramaJob& job);

// Global options shared by every subcommand.
struct GlobalOptions {
  bool quiet = false;
  bool verbose = false;
};
const GlobalOptions& global_options();

}  // namespace maquette::cli
