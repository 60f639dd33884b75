#include "exemplar_cache.h"

#include <cpl_conv.h>
#include <cpl_string.h>
#include <cpl_vsi.h>
#include <dlfcn.h>
#include <gdal_priv.h>
#include <openssl/evp.h>
#include <spdlog/spdlog.h>
#include <sys/stat.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <system_error>

#include "combined_exemplar.h"
#include "core/error.h"
#include "core/json_file.h"
#include "core/output_file.h"
#include "core/whole_int.h"
#include "exemplar_codec.h"
#include "exemplar_pyramid.h"
#include "gdal/gdal_env.h"
#include "painting.h"
#include "synthesis.h"

namespace maquette::synthesis {
namespace {

using Digest = std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)>;

void add(EVP_MD_CTX* sha, const void* data, size_t size) { EVP_DigestUpdate(sha, data, size); }

void add(EVP_MD_CTX* sha, const std::string& text) {
  const uint64_t size = text.size();
  add(sha, &size, sizeof size);
  add(sha, text.data(), text.size());
}

// The files of the dataset GDAL opens at `path`, or nothing when it opens none.
std::vector<std::string> dataset_files(const std::string& path) {
  const GdalSession gdal;  // a file GDAL cannot open is said by the reader, not here
  const std::unique_ptr<GDALDataset> dataset(GDALDataset::Open(
      path.c_str(), GDAL_OF_RASTER | GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, nullptr, nullptr));
  if (!dataset) return {};
  std::vector<std::string> out;
  char** list = dataset->GetFileList();
  for (char** f = list; f && *f; ++f) out.emplace_back(*f);
  CSLDestroy(list);
  return out;
}

// Adds the file's name, size and bytes (read through GDAL's virtual file system, as GDAL read
// them); false when it cannot be read.
bool add_file(EVP_MD_CTX* sha, const std::string& path) {
  VSILFILE* f = VSIFOpenL(path.c_str(), "rb");
  if (!f) return false;
  add(sha, path);
  std::vector<char> chunk(size_t(1) << 20);
  uint64_t size = 0;
  for (size_t n; (n = VSIFReadL(chunk.data(), 1, chunk.size(), f)) > 0; size += n)
    add(sha, chunk.data(), n);
  VSIFCloseL(f);
  add(sha, &size, sizeof size);
  return true;
}

// The build of the analysis: the path, size and modification time of the file (program or
// library) holding its code, so that a rebuild misses; null when it cannot be found. For code
// linked into the program glibc's dladdr gives argv[0], a bare name when run through PATH: the
// program is then /proc/self/exe.
nlohmann::json analysis_build() {
  Dl_info info{};
  if (!dladdr(reinterpret_cast<const void*>(&analyse_exemplar), &info) || !info.dli_fname)
    return nullptr;
  std::string path = info.dli_fname;
  std::error_code error;
  if (path.find('/') == std::string::npos)
    path = std::filesystem::read_symlink("/proc/self/exe", error).string();
  struct stat st {};
  if (error || stat(path.c_str(), &st) != 0) return nullptr;
  return {path, st.st_size, st.st_mtim.tv_sec, st.st_mtim.tv_nsec};
}

// What the key holds besides the params and files: the files' format, the release of GDAL (which
// decodes the painting) and the analysis's build. Without the build (the loader does not say),
// the analysis's constants instead: a change of its code then reads older files.
nlohmann::json analysis_identity() {
  nlohmann::json out = {{"format", kExemplarCacheVersion},
                        {"gdal", GDALVersionInfo("RELEASE_NAME")},
                        {"build", analysis_build()}};
  if (!out["build"].is_null()) return out;
  spdlog::debug("synthesis.transfer: the analysis's build is not in the exemplar cache's key");
  const SynthesisParams d;
  out["constants"] = {
      kLevels,
      kPatchRadius,
      kFeatureDims,
      kCombinedGap,
      kClassSmoothingRadius,
      kSpreadRegionShift,
      {d.w_label, d.w_altitude, d.w_distance, d.w_light, d.w_repetition, d.w_usage, d.w_spread,
       d.spread_typical, d.coherence, d.patch_passes, d.patch_balance, d.patch_search,
       d.patch_edges, d.vote_radius, d.vote_balance, d.jitter, d.depth_break, d.seed}};
  return out;
}

std::string hex(const unsigned char* bytes, unsigned size) {
  static constexpr char kDigits[] = "0123456789abcdef";
  std::string out;
  for (unsigned i = 0; i < size; ++i) {
    out += kDigits[bytes[i] >> 4];
    out += kDigits[bytes[i] & 15];
  }
  return out;
}

}  // namespace

std::optional<std::filesystem::path> exemplar_cache_dir() {
  if (const char* dir = std::getenv("MAQUETTE_CACHE_DIR"); dir && *dir)
    return std::string(dir) == "off" ? std::nullopt : std::optional<std::filesystem::path>(dir);
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
    return std::filesystem::path(xdg) / "maquette";
  if (const char* home = std::getenv("HOME"); home && *home)
    return std::filesystem::path(home) / ".cache" / "maquette";
  return std::nullopt;
}

std::optional<std::string> exemplar_cache_key(const nlohmann::json& params,
                                              const std::vector<std::string>& inputs) {
  const Digest sha(EVP_MD_CTX_new(), &EVP_MD_CTX_free);
  if (!sha || !EVP_DigestInit_ex(sha.get(), EVP_sha256(), nullptr)) return std::nullopt;
  add(sha.get(), analysis_identity().dump());
  add(sha.get(), params.dump());
  for (const std::string& input : inputs) {
    const auto files = dataset_files(input);
    if (files.empty()) return std::nullopt;
    for (const std::string& file : files)
      if (!add_file(sha.get(), file)) return std::nullopt;
  }
  std::array<unsigned char, EVP_MAX_MD_SIZE> digest{};
  unsigned size = 0;
  if (!EVP_DigestFinal_ex(sha.get(), digest.data(), &size)) return std::nullopt;
  return hex(digest.data(), size);
}

uintmax_t exemplar_cache_budget() {
  const char* text = std::getenv("MAQUETTE_CACHE_MAX_MB");
  if (!text || !*text) return kExemplarCacheDefaultMB * 1000000;
  const auto mb = whole_int<uintmax_t>(text);
  if (mb && *mb <= UINTMAX_MAX / 1000000) return *mb * 1000000;
  spdlog::warn("MAQUETTE_CACHE_MAX_MB={}: not a whole number of megabytes; keeping {} MB", text,
               kExemplarCacheDefaultMB);
  return kExemplarCacheDefaultMB * 1000000;
}

void prune_exemplar_cache(const std::filesystem::path& directory, uintmax_t budget,
                          const std::filesystem::path& keep) {
  namespace fs = std::filesystem;
  struct Entry {
    fs::file_time_type used;
    fs::path path;
    uintmax_t size;
  };
  std::vector<Entry> entries;
  uintmax_t total = 0;
  std::error_code error;
  for (fs::directory_iterator it(directory, error), end; !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (!name.starts_with("exemplar-") || !name.ends_with(".zst")) continue;
    std::error_code gone;  // deleted by another process meanwhile: not counted
    const uintmax_t size = it->file_size(gone);
    const auto used = it->last_write_time(gone);
    if (gone) continue;
    total += size;
    if (it->path() != keep) entries.push_back({used, it->path(), size});
  }
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    return a.used != b.used ? a.used < b.used : a.path < b.path;
  });
  for (const Entry& e : entries) {
    if (total <= budget) break;
    std::error_code kept;
    if (fs::remove(e.path, kept)) {
      total -= e.size;
      spdlog::debug("synthesis.transfer: the exemplar cache dropped {}", e.path.string());
    }
  }
}

std::filesystem::path exemplar_cache_file(const std::filesystem::path& directory,
                                          const std::string& key) {
  return directory / ("exemplar-" + key + ".zst");
}

std::shared_ptr<const TransferExemplar> cached_exemplar(
    const std::filesystem::path& directory, const std::string& key,
    const std::function<std::shared_ptr<const TransferExemplar>()>& analyse) {
  const std::filesystem::path file = exemplar_cache_file(directory, key);
  try {
    std::error_code missing;
    if (std::filesystem::exists(file, missing)) {
      auto exemplar = std::make_shared<const TransferExemplar>(
          decode_exemplar(read_text_file(file.string()), key));
      std::error_code ignored;  // used now: the last the budget drops
      std::filesystem::last_write_time(file, std::filesystem::file_time_type::clock::now(),
                                       ignored);
      return exemplar;
    }
  } catch (const std::exception& e) {
    spdlog::warn("synthesis.transfer: ignoring the cached exemplar {}: {}; analysing it again",
                 file.string(), e.what());
  }
  auto exemplar = analyse();
  std::error_code ignored;  // a directory that cannot be made: the write says why
  std::filesystem::create_directories(directory, ignored);
  try {
    write_file_whole(file.string(), encode_exemplar(*exemplar, key));
    prune_exemplar_cache(directory, exemplar_cache_budget(), file);
  } catch (const Error& e) {
    spdlog::warn("synthesis.transfer: the exemplar's analysis is not cached: {}", e.what());
  }
  return exemplar;
}

}  // namespace maquette::synthesis
