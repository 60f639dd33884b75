// maquette: ingest, run and export Digital Earth grids. See README.md.
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "core/error.h"
#include "core/malloc_tuning.h"
#include "gdal/gdal_env.h"

namespace maquette::cli {
namespace {
GlobalOptions g_options;
}
const GlobalOptions& global_options() { return g_options; }

void add_threads_option(CLI::App* cmd, int& threads) {
  cmd->add_option("-t,--threads", threads, "Worker threads (0: all cores)")
      ->capture_default_str()
      ->check(CLI::Range(0, 1024));
}
}  // namespace maquette::cli

namespace {

// An option of a fixed number of values (--bbox W S E N) or of one comma-separated list (--bands
// 4,3,2) takes just those: CLI11's vector options took the positionals after them too
// (`--bbox W S E N a.tif b.tif`: "received 6").
void stop_options_at_their_arguments(CLI::App& app) {
  for (CLI::Option* opt : app.get_options())
    if ((opt->get_expected_max() > 1 && opt->get_expected_min() == opt->get_expected_max()) ||
        opt->get_delimiter() != '\0')
      opt->allow_extra_args(false);
  for (CLI::App* sub : app.get_subcommands({})) stop_options_at_their_arguments(*sub);
}

// The command path of argv whose next word names no subcommand, as "maquette export: 'bogus' is
// not one of gtiff, png, ...": CLI11 said "A subcommand is required", not which word was wrong.
std::optional<std::string> unknown_subcommand(const CLI::App& app, int argc, char** argv) {
  const CLI::App* at = &app;
  std::string path = "maquette";
  for (int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    if (word.starts_with("-")) continue;  // the commands that hold subcommands take flags only
    const std::vector<const CLI::App*> subs = at->get_subcommands({});
    if (subs.empty()) return std::nullopt;
    const auto next = std::find_if(subs.begin(), subs.end(),
                                   [&](const CLI::App* sub) { return sub->get_name() == word; });
    if (next == subs.end()) {
      std::string names;
      for (const CLI::App* sub : subs) names += (names.empty() ? "" : ", ") + sub->get_name();
      return path + ": '" + word + "' is not one of " + names;
    }
    at = *next;
    path += " " + word;
  }
  return std::nullopt;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace maquette::cli;
  maquette::keep_tile_buffers_mapped();
  maquette::init_gdal();  // GDAL's errors become ours, with its message, not lines on stderr
  CLI::App app{
      "maquette: Digital Earth grids on rHEALPix (WGS84, aperture 4).\n"
      "Ingest data into a cell-indexed store, run operators from modules over cell ranges, "
      "export what the store holds.",
      "maquette"};
  app.set_version_flag("--version", std::string(MAQUETTE_VERSION_STRING));
  app.footer(
      "Environment:\n"
      "  MAQUETTE_MODULE_PATH   directories of modules, ':'-separated (then lib/maquette next to "
      "the program)\n"
      "  MAQUETTE_CACHE_DIR     where analysed paintings are cached (default "
      "$XDG_CACHE_HOME/maquette or ~/.cache/maquette; 'off': no cache)\n"
      "  MAQUETTE_CACHE_MAX_MB  the cache's budget in megabytes (the least recently used files go "
      "beyond it; its default in README.md)\n"
      "  GDAL_CACHEMAX, PROJ_DATA and GDAL's other settings apply to the files GDAL reads\n"
      "See README.md.");
  app.add_flag("-q,--quiet", g_options.quiet, "Only print errors");
  app.add_flag("-v,--verbose", g_options.verbose, "Print debug messages");
  app.require_subcommand(1);
  app.fallthrough();
  add_cells_command(app);
  add_ingest_command(app);
  add_info_command(app);
  add_modules_command(app);
  add_run_command(app);
  add_export_command(app);
  add_render_command(app);
  add_demo_command(app);
  add_view_command(app);
  stop_options_at_their_arguments(app);

  spdlog::set_default_logger(spdlog::stderr_color_mt("maquette"));
  spdlog::set_pattern("%^%l%$: %v");
  // Runs after every option is parsed and before the subcommand's callback.
  app.parse_complete_callback([] {
    spdlog::set_level(g_options.quiet     ? spdlog::level::err
                      : g_options.verbose ? spdlog::level::debug
                                          : spdlog::level::info);
  });
  try {
    app.parse(argc, argv);  // subcommand callbacks run here
  } catch (const CLI::ParseError& e) {
    // --help and --version come as ParseErrors of exit code 0: they print what was asked.
    if (const auto unknown =
            e.get_exit_code() != 0 ? unknown_subcommand(app, argc, argv) : std::nullopt) {
      std::fprintf(stderr, "maquette: error: %s\nRun with --help for more information.\n",
                   unknown->c_str());
      return e.get_exit_code();
    }
    return app.exit(e);
  } catch (const maquette::Error& e) {
    std::fprintf(stderr, "maquette: error: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "maquette: internal error: %s\n", e.what());
    return 3;
  }
  return 0;
}
