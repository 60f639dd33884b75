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

}  // namespace maquette
