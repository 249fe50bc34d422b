#include "model_file.hpp"

#include "commands.hpp"
#include "genmod/kernel/vm_format.hpp"
#include "genmod/models/implicit_gallery.hpp"

#include <array>
#include <bit>
#include <stdexcept>

namespace genmod::app {

Fn load_model(const std::string& path) { return load_vm(path); }

Fn load_implicit_model(const std::string& name, const models::ParameterValues& overrides) {
  const models::ImplicitModel* model = models::find_implicit_model(name);
  if (!model) {
    if (!overrides.empty()) throw UsageError("--param applies to gallery models, not to " + name);
    return load_model(name);
  }
  try {
    return models::build_implicit_model(*model, overrides);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
}

Tape load_planar_model(const std::string& path) {
  const Fn f = load_model(path);
  const std::uint64_t extra = f.input_mask() & ~std::uint64_t{3};
  if (extra != 0)
    throw std::runtime_error("genmod: '" + path + "' depends on x(" + std::to_string(std::countr_zero(extra)) +
                             "); a 2-D render takes models of x and y only");
  static constexpr std::array<int, 2> kXY{0, 1};
  return Tape(f, kXY);
}

}  // namespace genmod::app
