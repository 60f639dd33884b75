#include "core/output_clash.h"

#include <filesystem>

#include "core/error.h"

namespace maquette {

void check_outputs_spare_inputs(const std::vector<std::string>& outputs,
                                const std::vector<InputFile>& inputs) {
  for (const std::string& out : outputs)
    for (const InputFile& in : inputs) {
      std::error_code ec;  // either missing: not the same file
      if (std::filesystem::equivalent(out, in.path, ec))
        throw Error(out + " is " + in.what + " " + in.path +
                    ": it would be replaced; give another output path");
    }
}

void check_outputs_distinct(const std::vector<OutputName>& outputs) {
  namespace fs = std::filesystem;
  for (size_t i = 0; i < outputs.size(); ++i)
    for (size_t j = 0; j < i; ++j) {
      std::error_code ec;
      if (fs::weakly_canonical(outputs[i].path, ec) == fs::weakly_canonical(outputs[j].path, ec))
        throw Error(outputs[i].path + " is both " + outputs[j].what + " and " + outputs[i].what +
                    ": give them other paths");
    }
}

}  // namespace maquette
