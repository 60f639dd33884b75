#include "runtime/ranks.h"

#include <spdlog/fmt/fmt.h>

#include "core/error.h"

namespace maquette {
namespace {

class SingleProcess final : public Ranks {
 public:
  int rank() const override { return 0; }
  int size() const override { return 1; }
  std::vector<std::string> all_gather(const std::string& bytes) override { return {bytes}; }
};

}  // namespace

std::unique_ptr<Ranks> single_process() { return std::make_unique<SingleProcess>(); }

std::vector<std::string> exchange(Ranks& ranks, const std::function<std::string()>& fn) {
  if (ranks.size() == 1) return {fn()};
  // A message is "+payload" or "!error".
  std::string message;
  try {
    message = "+" + fn();
  } catch (const std::exception& e) {
    message = std::string("!") + e.what();
  } catch (...) {
    message = "!unknown exception";
  }
  std::vector<std::string> all = ranks.all_gather(message);
  for (size_t r = 0; r < all.size(); ++r)
    if (all[r].front() == '!')
      throw Error(fmt::format("rank {} of {}: {}", r, all.size(), all[r].substr(1)));
  for (std::string& m : all) m.erase(0, 1);
  return all;
}

}  // namespace maquette
