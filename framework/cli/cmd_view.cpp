// maquette view OUTDIR: serves the web viewer (viewer/, bundled into share/maquette/viewer) and
// the 3D Tiles export in OUTDIR on 127.0.0.1 until interrupted. The server is the viewer plug-in
// (plugins/view_server.h), opened once the options are checked.
#include <filesystem>
#include <string>

#include "cli/commands.h"
#include "core/error.h"
#include "plugins/view_server.h"
#include "runtime/plugin.h"

namespace maquette::cli {
namespace {

namespace fs = std::filesystem;

void check_dirs(const ViewServeOptions& o) {
  if (!fs::is_directory(o.outdir))
    throw Error("view: " + o.outdir +
                " is not a directory (give the OUTDIR of `maquette export tiles3d`)");
  if (!fs::is_regular_file(fs::path(o.outdir) / "tileset.json"))
    throw Error("view: " + o.outdir +
                " has no tileset.json (write one with `maquette export tiles3d STORE " + o.outdir +
                " --dem LAYER`)");
  if (!fs::is_regular_file(fs::path(o.viewer) / "index.html") ||
      !fs::is_regular_file(fs::path(o.viewer) / "app.js"))
    throw Error(
        "view: no viewer bundle in " + o.viewer +
        " (index.html, app.js); it is built by the CMake target maquette_viewer, which needs "
        "npm: install npm, re-run cmake and build (`cmake --build build --target "
        "maquette_viewer`), or pass --viewer DIR");
  if (o.port < 0 || o.port > 65535)
    throw Error("view: --port " + std::to_string(o.port) +
                " is not a port (0..65535; 0 picks a free one)");
}

void serve(const ViewServeOptions& opts) {
  ViewServeOptions o = opts;
  // build/bin/maquette -> build/share/maquette/viewer (the install layout is the same).
  if (o.viewer.empty()) o.viewer = (program_prefix() / "share" / "maquette" / "viewer").string();
  o.quiet = global_options().quiet;
  check_dirs(o);
  plugin_function<decltype(maquette_view_serve)>(kViewPlugin, kViewServeEntry)(o);
}

}  // namespace

void add_view_command(CLI::App& app) {
  auto opts = std::make_shared<ViewServeOptions>();
  CLI::App* cmd = app.add_subcommand(
      "view", "Serve a 3D Tiles export and the web viewer on 127.0.0.1 until interrupted");
  cmd->add_option("OUTDIR", opts->outdir,
                  "Folder written by `maquette export tiles3d` (has tileset.json)")
      ->required();
  cmd->add_option("--port", opts->port, "Port on 127.0.0.1 (0 picks a free one)")
      ->capture_default_str();
  cmd->add_option("--viewer", opts->viewer,
                  "Folder of the viewer bundle (default: share/maquette/viewer next to bin/)");
  cmd->callback([opts] { serve(*opts); });
}

}  // namespace maquette::cli
