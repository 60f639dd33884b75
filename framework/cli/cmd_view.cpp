// maquette view OUTDIR: serves the web viewer (viewer/, bundled into share/maquette/viewer) and
// the 3D Tiles export in OUTDIR on 127.0.0.1 until interrupted.
#include <httplib.h>
#include <signal.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <string>
#include <thread>

#include "cli/commands.h"
#include "core/error.h"

namespace maquette::cli {
namespace {

namespace fs = std::filesystem;

struct ViewOptions {
  std::string outdir;
  int port = 8000;
  std::string viewer;
};

// build/bin/maquette -> build/share/maquette/viewer (the install layout is the same).
std::string default_viewer_dir() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  const fs::path base = ec ? fs::path("..") : exe.parent_path().parent_path();
  return (base / "share" / "maquette" / "viewer").string();
}

int g_wake[2] = {-1, -1};
extern "C" void on_signal(int) {
  const char c = 's';
  [[maybe_unused]] const auto n = write(g_wake[1], &c, 1);
}

void check_dirs(const ViewOptions& o) {
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

void configure(httplib::Server& svr, const ViewOptions& o) {
  // MIME types set explicitly: the library's table lacks some (glb, wasm) that browsers need.
  const std::pair<const char*, const char*> types[] = {
      {"html", "text/html; charset=utf-8"},
      {"js", "text/javascript; charset=utf-8"},
      {"mjs", "text/javascript; charset=utf-8"},
      {"css", "text/css; charset=utf-8"},
      {"json", "application/json"},
      {"txt", "text/plain; charset=utf-8"},
      {"glb", "model/gltf-binary"},
      {"gltf", "model/gltf+json"},
      {"bin", "application/octet-stream"},
      {"drc", "application/octet-stream"},
      {"subtree", "application/octet-stream"},
      {"wasm", "application/wasm"},
      {"png", "image/png"},
      {"jpg", "image/jpeg"},
      {"jpeg", "image/jpeg"},
      {"webp", "image/webp"},
      {"ktx2", "image/ktx2"},
  };
  for (const auto& [ext, mime] : types) svr.set_file_extension_and_mimetype_mapping(ext, mime);
  // Both folders are served at /: the viewer's files first, then the export (so ./tileset.json,
  // the viewer's default, is OUTDIR/tileset.json). The library refuses paths that leave them.
  if (!svr.set_mount_point("/", o.viewer)) throw Error("view: cannot serve " + o.viewer);
  if (!svr.set_mount_point("/", o.outdir)) throw Error("view: cannot serve " + o.outdir);
  svr.set_default_headers({{"Cache-Control", "no-cache"}});
  svr.set_logger([](const httplib::Request& req, const httplib::Response& res) {
    spdlog::debug("{} {} -> {}", req.method, req.path, res.status);
  });
}

void serve(const ViewOptions& opts) {
  ViewOptions o = opts;
  if (o.viewer.empty()) o.viewer = default_viewer_dir();
  check_dirs(o);

  httplib::Server svr;
  configure(svr, o);
  const std::string host = "127.0.0.1";
  int port = o.port;
  if (port == 0) {
    port = svr.bind_to_any_port(host);
    if (port <= 0) throw Error("view: cannot bind a port on " + host);
  } else if (!svr.bind_to_port(host, port)) {
    throw Error("view: cannot listen on " + host + ":" + std::to_string(port) +
                " (port in use?); pick another with --port P, or --port 0 for a free one");
  }

  // Ctrl-C (SIGINT) or SIGTERM stops the server cleanly: the handler (which may run on any
  // thread) writes to a pipe the main thread waits on; the server thread writes to it too if it
  // stops by itself.
  if (pipe(g_wake) != 0) throw Error("view: cannot create a pipe");
  struct sigaction sa {
  }, old_int{}, old_term{};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, &old_int);
  sigaction(SIGTERM, &sa, &old_term);
  std::atomic<bool> listen_failed = false;
  std::thread server([&] {
    listen_failed = !svr.listen_after_bind();
    const char c = 'e';
    [[maybe_unused]] const auto n = write(g_wake[1], &c, 1);
  });
  const std::string url = "http://" + host + ":" + std::to_string(port) + "/";
  std::printf("Serving the viewer and %s at %s (Ctrl-C to stop)\n", o.outdir.c_str(), url.c_str());
  std::fflush(stdout);
  char why = 0;
  while (read(g_wake[0], &why, 1) < 0 && errno == EINTR) {
  }
  svr.stop();
  server.join();
  sigaction(SIGINT, &old_int, nullptr);
  sigaction(SIGTERM, &old_term, nullptr);
  close(g_wake[0]);
  close(g_wake[1]);
  if (why == 'e' && listen_failed) throw Error("view: the server on " + url + " stopped");
  if (!global_options().quiet) std::printf("Stopped.\n");
}

}  // namespace

void add_view_command(CLI::App& app) {
  auto opts = std::make_shared<ViewOptions>();
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
