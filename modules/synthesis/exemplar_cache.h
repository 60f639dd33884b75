// A persistent cache of analysed exemplars (transfer_exemplar.h), as PROJ and GDAL cache their
// downloads: the analysis (seconds of CPU) is done once per set of inputs and read back by every
// later run, process and MPI rank. One file per key in the cache directory, written under a
// temporary name and renamed (several processes may store the same key at once); a file that
// cannot be read back whole and valid is ignored with a warning, recomputed and rewritten; a
// directory that cannot be written is a warning, never an error. Kept within a budget: after each
// store the least recently used files go (as PROJ's cache of grids keeps to its size).
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "transfer_exemplar.h"

namespace maquette::synthesis {

// The cache directory: $MAQUETTE_CACHE_DIR when set (the value "off": no cache, nullopt), else
// $XDG_CACHE_HOME/maquette, else $HOME/.cache/maquette (nullopt without HOME). Not created here.
std::optional<std::filesystem::path> exemplar_cache_dir();

// The key of an analysis that reads `params` (the exemplar's params only, canonical JSON) and
// the files `inputs` (each as GDAL opens it, with every file of its dataset: sidecars, a
// shapefile's parts): SHA-256, as 64 hex digits, of kExemplarCacheVersion (the files' format),
// GDAL's release (it decodes the painting; not the codec libraries it calls, libjpeg, libpng),
// the build (the path, size and modification time of the program or library holding the
// analysis: a rebuild misses, so a change of the analysis never reads an older build's file;
// where the build cannot be found, the analysis's constants instead: levels, patch and feature
// sizes, the paintings' gap, the segmentation's radius, the default SynthesisParams the usage is
// measured with), `params` and every file's name, size and bytes. nullopt when an input is no
// dataset GDAL opens or a file cannot be read (the analysis then reports it; nothing is cached).
std::optional<std::string> exemplar_cache_key(const nlohmann::json& params,
                                              const std::vector<std::string>& inputs);

// The cache's budget in bytes: $MAQUETTE_CACHE_MAX_MB megabytes (10^6 bytes; a whole number, 0
// keeping only the file just stored) when set, else kExemplarCacheDefaultMB. A value that is no
// whole number is a warning naming it, and the default.
inline constexpr uintmax_t kExemplarCacheDefaultMB = 500;  // ~30 analyses of ~16 MB
uintmax_t exemplar_cache_budget();

// Deletes the least recently used exemplar files (`exemplar-*.zst`) of `directory`, the oldest
// modification time first (cached_exemplar() touches a file it reads; ties by name), until those
// left hold at most `budget` bytes. `keep` (the file just stored) is never deleted, nor any other
// file. A file another process deletes meanwhile, or that cannot be deleted, is skipped.
void prune_exemplar_cache(const std::filesystem::path& directory, uintmax_t budget,
                          const std::filesystem::path& keep);

// The exemplar of `key` read from `directory` (its file's modification time set to now: used),
// else `analyse()`'s, stored there, then the directory pruned to exemplar_cache_budget().
std::shared_ptr<const TransferExemplar> cached_exemplar(
    const std::filesystem::path& directory, const std::string& key,
    const std::function<std::shared_ptr<const TransferExemplar>()>& analyse);

// The file of `key` in `directory`.
std::filesystem::path exemplar_cache_file(const std::filesystem::path& directory,
                                          const std::string& key);

}  // namespace maquette::synthesis
