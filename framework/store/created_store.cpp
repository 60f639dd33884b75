#include "store/created_store.h"

#include <filesystem>
#include <string>

namespace maquette {

void remove_if_created(std::unique_ptr<Store> store) noexcept {
  const bool ours = store->created();
  const std::string path = store->path();
  store.reset();
  std::error_code ec;
  if (ours)
    for (const char* suffix : {"", "-wal", "-shm", "-journal"})
      std::filesystem::remove(path + suffix, ec);
}

}  // namespace maquette
