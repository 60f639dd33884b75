// The warnings spdlog logs while a Warnings lives, as text (tests of what a user is told).
#pragma once

#include <spdlog/sinks/ostream_sink.h>
#include <spdlog/spdlog.h>

#include <memory>
#include <sstream>

namespace maquette::synthesis {

struct Warnings {
  std::ostringstream text;
  std::shared_ptr<spdlog::sinks::ostream_sink_mt> sink =
      std::make_shared<spdlog::sinks::ostream_sink_mt>(text);
  Warnings() { spdlog::default_logger()->sinks().push_back(sink); }
  ~Warnings() { std::erase(spdlog::default_logger()->sinks(), sink); }
};

}  // namespace maquette::synthesis
