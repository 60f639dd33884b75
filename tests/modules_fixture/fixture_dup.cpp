// A module defining "fixture.fill" again: loading it with good/ must fail naming both files.
#include <memory>

#include "runtime/module_abi.h"

namespace {

class Fill : public maquette::CellOperator {
 public:
  const maquette::OperatorSpec& spec() const override {
    static const maquette::OperatorSpec s = [] {
      maquette::OperatorSpec s;
      s.name = "fixture.fill";
      s.description = "duplicate of fixture.fill";
      s.outputs.resize(1);
      s.outputs[0].name = "value";
      return s;
    }();
    return s;
  }
  void run(const maquette::CellContext&, maquette::CellData&) const override {}
};

std::unique_ptr<maquette::Operator> make_fill() { return std::make_unique<Fill>(); }

}  // namespace

MAQUETTE_MODULE("fixture_dup", "0.0.1", "Defines fixture.fill a second time",
                {"fixture.fill", &make_fill})
