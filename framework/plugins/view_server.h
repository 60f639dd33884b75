// The viewer plug-in, libmaquette_view.so: the HTTP server of `maquette view` (cpp-httplib), opened
// by that command only, so no other command loads the HTTP library.
#pragma once

#include <string>

namespace maquette {

inline constexpr const char* kViewPlugin = "libmaquette_view.so";
inline constexpr const char* kViewServeEntry = "maquette_view_serve";

// What `maquette view` serves, checked by the command: the folders exist and hold a tileset and a
// viewer bundle, and the port is in 0..65535.
struct ViewServeOptions {
  std::string outdir;  // the export of `maquette export tiles3d`
  std::string viewer;  // the viewer bundle (index.html, app.js)
  int port = 8000;     // on 127.0.0.1; 0 picks a free one
  bool quiet = false;  // no "Stopped." at the end
};

}  // namespace maquette

// Serves the viewer and the export at / on 127.0.0.1:port until SIGINT or SIGTERM. Throws
// maquette::Error when the port cannot be bound or the server stops by itself.
extern "C" void maquette_view_serve(const maquette::ViewServeOptions& options);
