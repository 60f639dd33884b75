// The server of `maquette view`, in the viewer plug-in.
#include "plugins/view_server.h"

#include <httplib.h>
#include <signal.h>
#include <spdlog/spdlog.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <memory>
#include <string>
#include <thread>

#include "core/error.h"

namespace maquette {
namespace {

int g_wake[2] = {-1, -1};
extern "C" void on_signal(int) {
  const char c = 's';
  [[maybe_unused]] const auto n = write(g_wake[1], &c, 1);
}

void configure(httplib::Server& svr, const ViewServeOptions& o) {
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
  // Files are sent as they are, from a provider of known length, which the library does not
  // compress: it would compress text types (scripts, JSON) on the fly at brotli's slowest setting,
  // some 50 s for CesiumJS's 6 MB Cesium.js and seconds for the viewer's app.js, which on
  // 127.0.0.1 only costs time.
  svr.set_file_request_handler([](const httplib::Request&, httplib::Response& res) {
    if (res.body.empty()) return;
    auto body = std::make_shared<const std::string>(std::move(res.body));
    res.body.clear();
    res.set_content_provider(body->size(), res.get_header_value("Content-Type"),
                             [body](size_t offset, size_t length, httplib::DataSink& sink) {
                               return sink.write(body->data() + offset, length);
                             });
  });
  svr.set_logger([](const httplib::Request& req, const httplib::Response& res) {
    spdlog::debug("{} {} -> {}", req.method, req.path, res.status);
  });
}

// SO_REUSEADDR only (a restart may bind while the last run's connections linger in TIME_WAIT).
// The library's default adds SO_REUSEPORT, with which a second server binds a port already
// served and the two then answer in turn.
void exclusive_port(socket_t sock) {
  const int yes = 1;
  setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
}

void serve(const ViewServeOptions& o) {
  httplib::Server svr;
  configure(svr, o);
  svr.set_socket_options(exclusive_port);
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
  if (!o.quiet) std::printf("Stopped.\n");
}

}  // namespace
}  // namespace maquette

extern "C" void maquette_view_serve(const maquette::ViewServeOptions& options) {
  maquette::serve(options);
}
