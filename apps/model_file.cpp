#include "model_file.hpp"

#include "genmod/kernel/vm_format.hpp"

#include <array>
#include <bit>
#include <filesystem>
#include <stdexcept>

namespace genmod::app {

Fn load_model(const std::string& path) {
  // load_vm reports unreadable files; a directory opens fine as a stream, so check first.
  if (std::filesystem::is_directory(path))
    throw std::runtime_error("genmod: '" + path + "' is a directory, not a model");
  return load_vm(path);
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
