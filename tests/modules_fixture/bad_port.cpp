// A module whose operator declares an output of kind model, which no operator may write (model
// layers come from `maquette ingest --as model`): loading it must fail naming file and port.
#include <memory>

#include "runtime/module_abi.h"

namespace {

class WritesModel : public maquette::CellOperator {
 public:
  const maquette::OperatorSpec& spec() const override {
    static const maquette::OperatorSpec s = [] {
      maquette::OperatorSpec s;
      s.name = "fixture.writes_model";
      s.description = "declares a model output";
      s.outputs.resize(1);
      s.outputs[0].name = "prototype";
      s.outputs[0].kind = maquette::LayerKind::Model;
      return s;
    }();
    return s;
  }
  void run(const maquette::CellContext&, maquette::CellData&) const override {}
};

std::unique_ptr<maquette::Operator> make_writes_model() { return std::make_unique<WritesModel>(); }

}  // namespace

MAQUETTE_MODULE("fixture_bad_port", "0.0.1", "Declares an output of kind model",
                {"fixture.writes_model", &make_writes_model})
