#include "prospero.hpp"

#include "genmod/kernel/vm_format.hpp"

namespace genmod::bench {

const Tape& prospero_tape() {
  static const Tape tape(load_vm(GENMOD_DATA_DIR "/prospero.vm"));
  return tape;
}

}  // namespace genmod::bench
