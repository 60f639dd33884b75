// The one exception type of Maquette: a message meant for the user, naming the file, field
// and value at fault. The CLI prints it and exits non-zero.
#pragma once

#include <stdexcept>
#include <string>

namespace maquette {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace maquette
