// `maquette view` through the real program: bad input is refused with a message that says what
// to do; a good OUTDIR is served (tileset and viewer files with the right MIME types) and Ctrl-C
// stops the server cleanly; the server is a plug-in only `maquette view` loads, and a missing one
// is named. The browser test is e2e.mjs (CTest viewer_e2e).
#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <httplib.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "run_cli.h"

namespace fs = std::filesystem;
using maquette::test::install_without_plugins;
using maquette::test::plugin_path;
using maquette::test::run_maquette;
using maquette::test::run_maquette_limited;
using maquette::test::run_maquette_traced;
using maquette::test::spawn_maquette;
using maquette::test::start_trace;
using maquette::test::temp_dir;

namespace {

void write_file(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << text;
}

// A fake viewer bundle and a minimal export.
struct Dirs {
  std::string viewer, outdir;
};
Dirs make_dirs() {
  const fs::path root = temp_dir();
  write_file(root / "viewer" / "index.html", "<!doctype html><title>v</title>");
  write_file(root / "viewer" / "app.js", "console.log(1)");
  write_file(root / "viewer" / "draco" / "draco_decoder.wasm", std::string("\0asm", 4));
  write_file(root / "out" / "tileset.json", R"({"asset":{"version":"1.1"}})");
  write_file(root / "out" / "tiles" / "Q1.glb", "glTF");
  return {(root / "viewer").string(), (root / "out").string()};
}

// A port on 127.0.0.1 held open (listening) while the object lives.
struct HeldPort {
  int fd = -1;
  int port = 0;
  HeldPort() {
    fd = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    a.sin_port = 0;
    bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a);
    listen(fd, 1);
    socklen_t len = sizeof a;
    getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len);
    port = ntohs(a.sin_port);
  }
  ~HeldPort() { close(fd); }
};

// A port that was free a moment ago.
int free_port() {
  HeldPort probe;
  return probe.port;
}

// GET `path` from the server on `port`, retried for up to 5 s while it starts.
httplib::Result get_when_up(httplib::Client& cli, const std::string& path) {
  cli.set_connection_timeout(1);
  auto res = cli.Get(path);
  for (int i = 0; i < 50 && !res; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    res = cli.Get(path);
  }
  return res;
}

// Stops a `maquette view` with Ctrl-C and returns its wait status.
int interrupt(int pid) {
  kill(pid, SIGINT);
  int status = 0;
  waitpid(pid, &status, 0);
  return status;
}

}  // namespace

TEST(ViewCli, RefusesOutdirWithoutTileset) {
  const Dirs d = make_dirs();
  fs::remove(fs::path(d.outdir) / "tileset.json");
  const auto r = run_maquette("view " + d.outdir + " --viewer " + d.viewer + " --port 0");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("no tileset.json"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("export tiles3d"), std::string::npos) << r.err;
}

TEST(ViewCli, RefusesMissingOutdir) {
  const Dirs d = make_dirs();
  const auto r = run_maquette("view " + d.outdir + "/nope --viewer " + d.viewer);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("is not a directory"), std::string::npos) << r.err;
}

TEST(ViewCli, RefusesMissingViewerBundleAndSaysHowToBuildIt) {
  const Dirs d = make_dirs();
  const auto r = run_maquette("view " + d.outdir + " --viewer " + d.outdir + "/no-viewer --port 0");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("no viewer bundle"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("maquette_viewer"), std::string::npos) << r.err;
}

// Refused after the viewer plug-in, with the HTTP library, is loaded (the loader's trace, as in
// OnlyViewLoadsTheHttpLibrary below).
TEST(ViewCli, RefusesPortInUse) {
  const Dirs d = make_dirs();
  HeldPort held;
  ASSERT_GT(held.port, 0);
  const auto r = run_maquette_traced("view " + d.outdir + " --viewer " + d.viewer + " --port " +
                                     std::to_string(held.port));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("in use"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("file=" + plugin_path("libmaquette_view.so")), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("libcpp-httplib"), std::string::npos) << r.err;
}

// A second `maquette view` on the port of a running one is refused (cpp-httplib's default socket
// options share the port with SO_REUSEPORT: both would serve, answering in turn); the first
// goes on serving.
TEST(ViewCli, RefusesThePortOfARunningView) {
  const Dirs d = make_dirs();
  const int port = free_port();
  const std::string args =
      "view " + d.outdir + " --viewer " + d.viewer + " --port " + std::to_string(port);
  const int pid = spawn_maquette(args);
  ASSERT_GT(pid, 0);
  httplib::Client cli("127.0.0.1", port);
  ASSERT_TRUE(get_when_up(cli, "/tileset.json")) << "maquette view did not answer on " << port;

  const auto second = run_maquette_limited(args, 10);
  EXPECT_NE(second.exit_code, 0) << second.out;
  EXPECT_NE(second.err.find("127.0.0.1:" + std::to_string(port) + " (port in use?)"),
            std::string::npos)
      << second.err;
  EXPECT_EQ(second.out.find("Serving"), std::string::npos) << second.out;
  auto res = cli.Get("/tileset.json");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 200);

  const int status = interrupt(pid);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
}

TEST(ViewCli, RefusesBadPort) {
  const Dirs d = make_dirs();
  const auto r = run_maquette("view " + d.outdir + " --viewer " + d.viewer + " --port 70000");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("--port"), std::string::npos) << r.err;
}

TEST(ViewCli, ServesViewerAndTilesetWithMimeTypesAndStopsOnSigint) {
  const Dirs d = make_dirs();
  const int port = free_port();
  const int pid = spawn_maquette("view " + d.outdir + " --viewer " + d.viewer + " --port " +
                                 std::to_string(port));
  ASSERT_GT(pid, 0);
  httplib::Client cli("127.0.0.1", port);
  auto res = get_when_up(cli, "/tileset.json");
  ASSERT_TRUE(res) << "maquette view did not answer on port " << port;
  EXPECT_EQ(res->status, 200);
  EXPECT_EQ(res->get_header_value("Content-Type"), "application/json");
  const auto check = [&](const std::string& path, const std::string& mime) {
    auto r = cli.Get(path);
    ASSERT_TRUE(r) << path;
    EXPECT_EQ(r->status, 200) << path;
    EXPECT_EQ(r->get_header_value("Content-Type").rfind(mime, 0), 0u)
        << path << ": " << r->get_header_value("Content-Type");
  };
  check("/", "text/html");
  check("/app.js", "text/javascript");
  check("/tiles/Q1.glb", "model/gltf-binary");
  check("/draco/draco_decoder.wasm", "application/wasm");
  auto missing = cli.Get("/tiles/none.glb");
  ASSERT_TRUE(missing);
  EXPECT_EQ(missing->status, 404);
  auto escape = cli.Get("/../../etc/passwd");
  ASSERT_TRUE(escape);
  EXPECT_NE(escape->status, 200);

  const int status = interrupt(pid);
  EXPECT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 0);
}

// Files are sent as they are, even to a browser that accepts compressed ones: the library would
// compress scripts and JSON on the fly with brotli's slowest setting (some 50 s for CesiumJS's
// 6 MB Cesium.js, in tests/viewer/cesium.mjs), which on 127.0.0.1 only costs time.
TEST(ViewCli, SendsFilesUncompressed) {
  const Dirs d = make_dirs();
  std::string script;
  for (int i = 0; script.size() < 300000; ++i)
    script += "var v" + std::to_string(i) + " = " + std::to_string(i * 7919 % 1000) + ";\n";
  write_file(fs::path(d.viewer) / "big.js", script);
  const int port = free_port();
  const int pid = spawn_maquette("view " + d.outdir + " --viewer " + d.viewer + " --port " +
                                 std::to_string(port));
  ASSERT_GT(pid, 0);
  httplib::Client cli("127.0.0.1", port);
  cli.set_decompress(false);
  ASSERT_TRUE(get_when_up(cli, "/tileset.json"));
  for (const auto& [path, file] :
       {std::pair{"/big.js", fs::path(d.viewer) / "big.js"},
        std::pair{"/tileset.json", fs::path(d.outdir) / "tileset.json"}}) {
    auto res = cli.Get(path, {{"Accept-Encoding", "gzip, deflate, br"}});
    ASSERT_TRUE(res) << path;
    EXPECT_EQ(res->status, 200) << path;
    EXPECT_FALSE(res->has_header("Content-Encoding"))
        << path << ": " << res->get_header_value("Content-Encoding");
    std::ifstream in(file, std::ios::binary);
    EXPECT_EQ(res->body, std::string(std::istreambuf_iterator<char>(in), {})) << path;
  }
  const int status = interrupt(pid);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
}

// The dynamic loader's trace (LD_DEBUG=files) names every library a process loads: the HTTP
// library comes with the viewer plug-in, loaded by `maquette view` (RefusesPortInUse above) and
// by no other command.
TEST(ViewCli, OnlyViewLoadsTheHttpLibrary) {
  const std::string trace = start_trace();
  EXPECT_EQ(trace.find("libcpp-httplib"), std::string::npos) << trace;
  EXPECT_EQ(trace.find("libmaquette_view.so"), std::string::npos) << trace;
}

// A copy of the program in PREFIX/bin without PREFIX/lib, so without its plug-ins.
TEST(ViewCli, MissingPluginIsNamed) {
  const Dirs d = make_dirs();
  const fs::path prefix = temp_dir();
  const std::string program = install_without_plugins(prefix);
  const fs::path err = prefix / "stderr";
  const int status = std::system(
      (program + " view " + d.outdir + " --viewer " + d.viewer + " --port 0 2>" + err.string())
          .c_str());
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) != 0);
  std::ifstream in(err);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(
      text.find("cannot load the plug-in " + (prefix / "lib" / "libmaquette_view.so").string()),
      std::string::npos)
      << text;
}
