// Outputs that would replace a command's inputs: a careless OUT (`render panorama s.mqt s.mqt`)
// replaced the store by a picture, exit 0.
#pragma once

#include <string>
#include <vector>

namespace maquette {

// An input a command reads, named for messages: {"the store", "s.mqt"}.
struct InputFile {
  std::string what, path;
};

// Throws maquette::Error when one of `outputs` is one of `inputs` (the same file, however its path
// is spelled; a path that does not exist is no input): "s.mqt is the store s.mqt: it would be
// replaced; give another output path".
void check_outputs_spare_inputs(const std::vector<std::string>& outputs,
                                const std::vector<InputFile>& inputs);

// An output file a command writes, named for messages: {"--panorama", "p.png"}.
struct OutputName {
  std::string what, path;
};

// Throws maquette::Error when two of `outputs` are one file (however spelled; the later would
// replace the earlier): "p.png is both OUT and --panorama: give them other paths".
void check_outputs_distinct(const std::vector<OutputName>& outputs);

}  // namespace maquette
