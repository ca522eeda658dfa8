// Bit-identity of two forms of one computation (a scalar form and its eight-wide twin), asserted where the build
// fixes the arithmetic. The Release build (-O2 and up) contracts a scalar a * b + c into the fused multiply-add
// that the eight-wide form writes out, so the two give the same bits, and a result may depend on it. The
// sanitizer build (make sanitize, -O1; SPH_ARITHMETIC_UNFIXED) does not contract, so there the forms differ in
// the last bits and agree within a few roundings of the quantity's scale: each of the few roundings of a kernel
// evaluation moves it by at most half an ulp of an intermediate no larger than a small multiple of the scale.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>

inline ::testing::AssertionResult same_bits(double a, double b, double scale) {
#ifdef SPH_ARITHMETIC_UNFIXED
  if (std::abs(a - b) <= 1e-14 * (std::abs(a) + scale)) return ::testing::AssertionSuccess();
  const char* how = "differ by more than 1e-14 of their scale";
#else
  (void)scale;
  if (std::memcmp(&a, &b, sizeof a) == 0) return ::testing::AssertionSuccess();
  const char* how = "differ in their bits";
#endif
  char text[96];
  std::snprintf(text, sizeof text, "%.17g and %.17g ", a, b);
  return ::testing::AssertionFailure() << text << how;
}
