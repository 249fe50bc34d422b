// An MPFR number that frees itself (test oracle helper).
#pragma once

#include <mpfr.h>

namespace genmod::testing {

class Mpfr {
 public:
  explicit Mpfr(mpfr_prec_t precision = 200) { mpfr_init2(v_, precision); }
  ~Mpfr() { mpfr_clear(v_); }
  Mpfr(const Mpfr&) = delete;
  Mpfr& operator=(const Mpfr&) = delete;
  mpfr_ptr get() { return v_; }

 private:
  mpfr_t v_;
};

}  // namespace genmod::testing
