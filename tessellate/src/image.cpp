#include "genmod/tessellate/image.hpp"

#include <stdexcept>
#include <string>

namespace genmod {

Image::Image(int w, int h, std::uint8_t value) : width(w), height(h) {
  if (w < 0 || h < 0)
    throw std::invalid_argument("genmod: Image: negative size " + std::to_string(w) + " x " + std::to_string(h));
  pixels.assign(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), value);
}

}  // namespace genmod
