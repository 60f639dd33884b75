// The persistent cache of analysed exemplars (exemplar_cache.h): a cached exemplar is the
// analysed one field by field and gives the transfer the same tiles; its key follows the files'
// bytes and the exemplar's params but not the synthesis's weights; a bad file is ignored, warned
// about and rewritten; "off" writes nothing; an unwritable directory is a warning.
#include "../exemplar_cache.h"

#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <latch>
#include <thread>

#include "../exemplar_codec.h"
#include "../transfer_exemplar.h"
#include "../transfer_params.h"
#include "core/error.h"
#include "logged_warnings.h"
#include "run_cli.h"
#include "runtime/params_schema.h"
#include "store/store.h"
#include "synthetic_raster.h"
#include "zion_ingest.h"

namespace maquette::synthesis {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A `size` x `size` RGB PNG of a colour ramp (pixel i's bands i * 7, i * 3, i * 11, modulo 256),
// with `changed` pixel's red one higher.
std::string painting_png(const std::string& path, int size, int changed = -1) {
  return test::write_png(path, size, size, 3, [size, changed](int x, int y, int b) {
    const int i = y * size + x;
    return double(uint8_t(i * (b == 0 ? 7 : b == 1 ? 3 : 11) + (b == 0 && i == changed)));
  });
}

// Validated transfer params (the schema's defaults filled) of `painting` in 3 colour classes.
json params(const std::string& painting, int scale = 1) {
  return validate_params(transfer_params_schema(),
                         {{"painting", painting},
                          {"classes", 3},
                          {"exemplar_scale", scale},
                          {"k", 2},
                          {"landcover_classes", {{"1", 0}}}},
                         "test");
}

std::string key_of(const json& p) {
  return exemplar_cache_key(exemplar_key_params(p), exemplar_input_files(p)).value();
}

// The files under `dir`, sorted.
std::vector<fs::path> cache_files(const fs::path& dir) {
  std::vector<fs::path> out;
  if (fs::exists(dir))
    for (const auto& entry : fs::recursive_directory_iterator(dir))
      if (entry.is_regular_file()) out.push_back(entry.path());
  std::sort(out.begin(), out.end());
  return out;
}

void expect_same(const TransferExemplar& a, const TransferExemplar& b) {
  EXPECT_EQ(a.scale, b.scale);
  ASSERT_EQ(a.parts.size(), b.parts.size());
  for (size_t p = 0; p < a.parts.size(); ++p) {
    EXPECT_EQ(a.parts[p].x0, b.parts[p].x0);
    EXPECT_EQ(a.parts[p].width, b.parts[p].width);
    EXPECT_EQ(a.parts[p].height, b.parts[p].height);
  }
  EXPECT_EQ(a.pyramid.k, b.pyramid.k);
  ASSERT_EQ(a.pyramid.levels.size(), b.pyramid.levels.size());
  for (size_t i = 0; i < a.pyramid.levels.size(); ++i) {
    const ExemplarLevel &x = a.pyramid.levels[i], &y = b.pyramid.levels[i];
    EXPECT_EQ(x.width, y.width);
    EXPECT_EQ(x.height, y.height);
    EXPECT_EQ(x.rgb, y.rgb);
    EXPECT_EQ(x.labels, y.labels);
    EXPECT_EQ(x.altitude, y.altitude);
    EXPECT_EQ(x.distance, y.distance);
    EXPECT_EQ(x.light, y.light);
    EXPECT_EQ(x.excluded, y.excluded);
    EXPECT_EQ(x.basis.mean, y.basis.mean);
    EXPECT_EQ(x.basis.axes, y.basis.axes);
    EXPECT_EQ(x.features, y.features);
    EXPECT_EQ(x.similar, y.similar);
    EXPECT_EQ(x.allowed, y.allowed);
    EXPECT_EQ(x.by_label, y.by_label);
    EXPECT_EQ(x.usage, y.usage);
    EXPECT_EQ(x.colour_excess, y.colour_excess);
    EXPECT_EQ(x.class_edges, y.class_edges);
    EXPECT_EQ(x.region_quantile, y.region_quantile);
  }
}

// Sets an environment variable (unset: nullptr) for its life.
struct SetEnv {
  std::string name;
  std::optional<std::string> old;
  SetEnv(const std::string& n, const char* value) : name(n) {
    if (const char* v = std::getenv(n.c_str())) old = v;
    value ? setenv(n.c_str(), value, 1) : unsetenv(n.c_str());
  }
  ~SetEnv() { old ? setenv(name.c_str(), old->c_str(), 1) : unsetenv(name.c_str()); }
};

TEST(ExemplarCache, TheDirectoryFromTheEnvironment) {
  const fs::path root = test::temp_dir();  // the variables' values: nothing is created
  const std::string home_dir = (root / "home").string(), cache = (root / "cache").string(),
                    xdg_dir = (root / "xdg").string();
  const SetEnv home("HOME", home_dir.c_str());
  {
    const SetEnv dir("MAQUETTE_CACHE_DIR", cache.c_str()), xdg("XDG_CACHE_HOME", xdg_dir.c_str());
    EXPECT_EQ(exemplar_cache_dir(), fs::path(cache));
  }
  {
    const SetEnv dir("MAQUETTE_CACHE_DIR", "off");
    EXPECT_EQ(exemplar_cache_dir(), std::nullopt);
  }
  const SetEnv dir("MAQUETTE_CACHE_DIR", nullptr);
  {
    const SetEnv xdg("XDG_CACHE_HOME", xdg_dir.c_str());
    EXPECT_EQ(exemplar_cache_dir(), root / "xdg" / "maquette");
  }
  const SetEnv xdg("XDG_CACHE_HOME", nullptr);
  EXPECT_EQ(exemplar_cache_dir(), root / "home" / ".cache" / "maquette");
}

TEST(ExemplarCache, TheKeyFollowsTheFilesAndTheExemplarsParamsNotTheWeights) {
  const std::string dir = test::temp_dir();
  const json p = params(painting_png(dir + "/painting.png", 64));
  const std::string key = key_of(p);
  EXPECT_EQ(key.size(), 64u);
  EXPECT_EQ(key_of(p), key);

  json weights = p;  // the synthesis's weights and seed: the same analysis
  weights["w_label"] = 5.0;
  weights["w_usage"] = 0.2;
  weights["seed"] = 7;
  EXPECT_EQ(key_of(weights), key);

  for (const auto& [field, value] : {std::pair<std::string, json>{"k", 3},
                                     {"exemplar_scale", 2},
                                     {"classes", 4},
                                     {"exclude_classes", {1}},
                                     {"landcover_classes", {{"1", {0, 1}}}},
                                     {"painting_altitude", "rows"},
                                     {"painting_light", "lightness"}}) {
    json changed = p;
    changed[field] = value;
    EXPECT_NE(key_of(changed), key) << field;
  }

  // One byte of the painting changed (one pixel's red), the same name: another key.
  painting_png(dir + "/painting.png", 64, 100);
  EXPECT_NE(key_of(p), key);
  // A class image's bytes are in the key too.
  json labelled = p;
  labelled["labels"] = painting_png(dir + "/labels.png", 64);
  const std::string with_labels = key_of(labelled);
  painting_png(dir + "/labels.png", 64, 5);
  EXPECT_NE(key_of(labelled), with_labels);
  // A file GDAL cannot open: no key (the analysis names it).
  EXPECT_EQ(exemplar_cache_key(exemplar_key_params(p), {dir + "/none.png"}), std::nullopt);
}

TEST(ExemplarCache, ACachedExemplarIsTheAnalysedOneFieldByField) {
  if (!fs::exists(kPainting)) GTEST_SKIP() << "../shared/data is absent";
  const std::string dir = test::temp_dir();
  const SetEnv env("MAQUETTE_CACHE_DIR", dir.c_str());
  json p = params(kPainting, 8);
  p["classes"] = 5;
  p["exclude_classes"] = {0};
  p["landcover_classes"] = {{"1", 1}, {"2", {2, 3}}};
  p["painting_altitude"] = "rows";
  p["painting_light"] = "lightness";
  const auto analysed = transfer_exemplar(p);
  const auto files = cache_files(dir);
  ASSERT_EQ(files.size(), 1u);
  EXPECT_EQ(files[0], exemplar_cache_file(dir, key_of(p)));
  const auto cached = cached_exemplar(dir, key_of(p), [] {
    ADD_FAILURE() << "analysed again";
    return std::shared_ptr<const TransferExemplar>();
  });
  ASSERT_TRUE(cached);
  EXPECT_NE(cached, analysed);
  expect_same(*cached, *analysed);
  EXPECT_GT(analysed->pyramid.levels[0].usage.size(), 0u);
  EXPECT_GT(analysed->pyramid.levels[0].light.size(), 0u);
  EXPECT_GT(analysed->pyramid.levels[0].class_edges.size(), 0u);
  for (const ExemplarLevel& level : analysed->pyramid.levels)
    EXPECT_EQ(level.region_quantile.size(), level.labels.size());
}

TEST(ExemplarCache, ABadFileIsIgnoredWarnedAboutAndRewritten) {
  const std::string dir = test::temp_dir();
  const json p = params(painting_png(dir + "/painting.png", 96, 3));
  const std::string key = key_of(p);
  const fs::path file = exemplar_cache_file(dir, key);
  int analyses = 0;
  const auto analyse = [&] {
    ++analyses;
    return transfer_exemplar(p);
  };
  cached_exemplar(dir, key, analyse);
  ASSERT_EQ(analyses, 1);
  const auto good = [&] {
    std::ifstream in(file, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  }();
  ASSERT_GT(good.size(), 100u);

  const std::vector<std::pair<std::string, std::string>> bad = {
      {"truncated", good.substr(0, good.size() / 2)},
      {"a payload byte changed",
       [&] {
         std::string b = good;
         b[good.size() - 40] = char(b[good.size() - 40] ^ 0x10);
         return b;
       }()},
      {"another magic", "X" + good.substr(1)},
      {"empty", ""}};
  for (const auto& [what, bytes] : bad) {
    std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
    const Warnings warnings;
    const auto again = cached_exemplar(dir, key, analyse);
    EXPECT_EQ(analyses, 2) << what;
    analyses = 1;
    EXPECT_NE(warnings.text.str().find("ignoring the cached exemplar " + file.string()),
              std::string::npos)
        << what << ": " << warnings.text.str();
    // Rewritten: read back whole, with no analysis nor warning.
    const Warnings none;
    expect_same(*cached_exemplar(dir, key, analyse), *again);
    EXPECT_EQ(analyses, 1) << what;
    EXPECT_EQ(none.text.str(), "") << what;
  }
  // Stored under another key (a file renamed): refused.
  EXPECT_THROW(decode_exemplar(good, "other"), Error);
}

// Writers of one key at once (as MPI ranks or processes are), started together, each leave a
// whole file: each either analysed (and wrote) or read the file back, at least one analysed, no
// temporary file is left, and the file reads back.
TEST(ExemplarCache, WritersOfOneKeyAtOnceLeaveAWholeFile) {
  const std::string dir = test::temp_dir();
  const json p = params(painting_png(dir + "/painting.png", 96, 11));
  const auto analysed = transfer_exemplar(p);
  const std::string key = key_of(p);
  constexpr int kWriters = 4;
  std::vector<std::shared_ptr<const TransferExemplar>> got(kWriters);
  std::vector<char> wrote(kWriters, 0);
  std::latch start(kWriters);
  std::vector<std::thread> writers;
  for (int i = 0; i < kWriters; ++i)
    writers.emplace_back([&, i] {
      start.arrive_and_wait();
      got[size_t(i)] = cached_exemplar(dir, key, [&] {
        wrote[size_t(i)] = 1;
        return analysed;
      });
    });
  for (auto& w : writers) w.join();
  EXPECT_GE(std::count(wrote.begin(), wrote.end(), 1), 1);
  for (int i = 0; i < kWriters; ++i) {
    ASSERT_TRUE(got[size_t(i)]) << i;
    if (wrote[size_t(i)]) {
      EXPECT_EQ(got[size_t(i)], analysed) << i;
    } else {  // read back from the file another wrote
      EXPECT_NE(got[size_t(i)], analysed) << i;
      expect_same(*got[size_t(i)], *analysed);
    }
  }
  EXPECT_EQ(cache_files(dir),
            (std::vector<fs::path>{exemplar_cache_file(dir, key), fs::path(dir) / "painting.png"}))
      << "a temporary file left";
  expect_same(*cached_exemplar(dir, key, [] { return std::shared_ptr<const TransferExemplar>(); }),
              *analysed);
}

TEST(ExemplarCache, OffWritesNothingAndAnUnwritableDirectoryIsAWarning) {
  const std::string dir = test::temp_dir();
  const SetEnv home("HOME", dir.c_str()), xdg("XDG_CACHE_HOME", (dir + "/xdg").c_str());
  {
    const SetEnv off("MAQUETTE_CACHE_DIR", "off");
    json p = params(painting_png(dir + "/off.png", 64, 9));
    EXPECT_EQ(transfer_exemplar(p)->pyramid.k, 2);
    EXPECT_EQ(cache_files(dir), std::vector<fs::path>{fs::path(dir) / "off.png"});
  }
  // Under a file: no directory can be made there (not even by root).
  const std::string blocked = dir + "/off.png/cache";
  const SetEnv env("MAQUETTE_CACHE_DIR", blocked.c_str());
  const Warnings warnings;
  json p = params(dir + "/off.png");
  p["k"] = 3;
  EXPECT_EQ(transfer_exemplar(p)->pyramid.k, 3);
  EXPECT_NE(warnings.text.str().find("not cached: cannot write " + blocked), std::string::npos)
      << warnings.text.str();
}

// Five exemplar files of 100 bytes used one after the other, the oldest the one just stored, and
// a file of another kind: pruned to 250 bytes, the three oldest others go (500 -> 200 bytes), the
// one stored and the other file stay.
TEST(ExemplarCache, PruningDropsTheLeastRecentlyUsedBeyondTheBudget) {
  const fs::path dir = test::temp_dir();
  const auto t0 = fs::file_time_type::clock::now() - std::chrono::hours(10);
  std::vector<fs::path> files;
  for (int i = 0; i < 5; ++i) {
    files.push_back(exemplar_cache_file(dir, std::string(64, char('a' + i))));
    std::ofstream(files.back(), std::ios::binary) << std::string(100, 'x');
    fs::last_write_time(files.back(), t0 + std::chrono::hours(i));
  }
  std::ofstream(dir / "notes.txt") << std::string(1000, 'x');
  fs::last_write_time(dir / "notes.txt", t0 - std::chrono::hours(1));

  prune_exemplar_cache(dir, 1000, files[0]);  // within the budget: nothing goes
  EXPECT_EQ(cache_files(dir).size(), 6u);
  prune_exemplar_cache(dir, 250, files[0]);
  EXPECT_EQ(cache_files(dir), (std::vector<fs::path>{files[0], files[4], dir / "notes.txt"}));
  prune_exemplar_cache(dir, 0, files[4]);  // a budget of 0 keeps the file stored alone
  EXPECT_EQ(cache_files(dir), (std::vector<fs::path>{files[4], dir / "notes.txt"}));
}

// A file read back is touched (the budget drops it last); storing a second key within a budget
// that holds one file drops the first.
TEST(ExemplarCache, AReadMarksItsFileUsedAndAStorePrunes) {
  const std::string dir = test::temp_dir();
  const json p = params(painting_png(dir + "/painting.png", 64, 21));
  const auto analyse = [&] { return transfer_exemplar(p); };
  const std::string key = key_of(p);
  const fs::path file = exemplar_cache_file(dir, key);
  cached_exemplar(dir, key, analyse);
  const auto old = fs::file_time_type::clock::now() - std::chrono::hours(5);
  fs::last_write_time(file, old);
  cached_exemplar(dir, key, [] {
    ADD_FAILURE() << "analysed again";
    return std::shared_ptr<const TransferExemplar>();
  });
  EXPECT_GT(fs::last_write_time(file), old + std::chrono::hours(4));

  const SetEnv budget("MAQUETTE_CACHE_MAX_MB", "0");
  json other = p;
  other["k"] = 3;
  cached_exemplar(dir, key_of(other), [&] { return transfer_exemplar(other); });
  EXPECT_EQ(cache_files(dir), (std::vector<fs::path>{exemplar_cache_file(dir, key_of(other)),
                                                     fs::path(dir) / "painting.png"}));
}

TEST(ExemplarCache, TheBudgetFromTheEnvironment) {
  {
    const SetEnv unset("MAQUETTE_CACHE_MAX_MB", nullptr);
    EXPECT_EQ(exemplar_cache_budget(), kExemplarCacheDefaultMB * 1000000);
  }
  {
    const SetEnv set("MAQUETTE_CACHE_MAX_MB", "20");
    EXPECT_EQ(exemplar_cache_budget(), 20000000u);
  }
  for (const char* bad : {"20MB", "-1", "lots", "99999999999999999999999"}) {
    const SetEnv set("MAQUETTE_CACHE_MAX_MB", bad);
    const Warnings warnings;
    EXPECT_EQ(exemplar_cache_budget(), kExemplarCacheDefaultMB * 1000000) << bad;
    EXPECT_NE(warnings.text.str().find(std::string("MAQUETTE_CACHE_MAX_MB=") + bad),
              std::string::npos)
        << warnings.text.str();
  }
}

// The real program twice on Zion with one cache: the second run reads the first's analysis (the
// file is not rewritten) and writes the same tiles.
TEST(ExemplarCacheZion, AWarmRunWritesTheTilesOfAColdOne) {
  if (!fs::exists(kPainting) || !fs::exists(kShared + "/zion/nlcd.tif"))
    GTEST_SKIP() << "../shared/data is absent";
  const std::string dir = test::temp_dir(), cache = dir + "/cache";
  json pipeline = {{"region", {{"bbox", {-113.03, 37.25, -113.00, 37.28}}}},
                   {"level", 10},
                   {"steps", zion_ingest_steps()}};
  pipeline["steps"].push_back({{"op", "synthesis.transfer"},
                               {"inputs", {{"landcover", "landcover"}}},
                               {"outputs", {{"rgb", "painted"}, {"source", "painted_source"}}},
                               {"params",
                                {{"painting", kPainting},
                                 {"classes", 8},
                                 {"exclude_classes", {0}},
                                 {"landcover_classes", {{"4", 3}, {"5", 4}, {"7", 2}}},
                                 {"exemplar_scale", 4}}}});
  std::vector<std::unique_ptr<Store>> stores;
  ino_t inode = 0;
  for (const char* run : {"cold", "warm"}) {
    pipeline["store"] = dir + "/" + run + ".mqt";
    std::ofstream(dir + "/" + run + ".json") << pipeline.dump(1);
    const auto r = test::run_maquette("run " + dir + "/" + run + ".json --quiet --threads 2",
                                      "MAQUETTE_CACHE_DIR=" + cache);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
    const auto files = cache_files(cache);
    ASSERT_EQ(files.size(), 1u) << run;
    struct stat st {};
    ASSERT_EQ(stat(files[0].c_str(), &st), 0);
    if (inode) {
      EXPECT_EQ(st.st_ino, inode) << "the warm run rewrote the cache file";
    }
    inode = st.st_ino;
    stores.push_back(Store::open(dir + "/" + run + ".mqt", Store::Mode::ReadOnly));
  }
  for (const char* layer : {"painted", "painted_source"}) {
    const auto cells = stores[0]->tile_cells(layer);
    ASSERT_GE(cells.size(), 2u);
    ASSERT_EQ(cells, stores[1]->tile_cells(layer));
    for (const CellId cell : cells)
      EXPECT_EQ(stores[0]->get_tile(layer, cell)->bytes, stores[1]->get_tile(layer, cell)->bytes)
          << layer << " " << cell.ToText();
  }
}

}  // namespace
}  // namespace maquette::synthesis
