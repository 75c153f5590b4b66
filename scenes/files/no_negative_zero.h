#pragma once
// Numbers written without a sign on zero: a quantity computed as -0.0 (a
// penetration that never happened, the rate of a constant pressure) is 0 to
// a reader, and "-0" in a CSV or JSON reads as a sign that means something.

#include <locale>

namespace railjoint {

/// Writes -0.0 as 0 and every other number as std::num_put does.
class NoNegativeZero : public std::num_put<char> {
 protected:
  iter_type do_put(iter_type out, std::ios_base& stream, char_type fill, double value) const override {
    return std::num_put<char>::do_put(out, stream, fill, value == 0.0 ? 0.0 : value);
  }
  iter_type do_put(iter_type out, std::ios_base& stream, char_type fill, long double value) const override {
    return std::num_put<char>::do_put(out, stream, fill, value == 0.0L ? 0.0L : value);
  }
};

/// `base` with NoNegativeZero for writing numbers (imbue it into a stream).
inline std::locale without_negative_zero(const std::locale& base) { return std::locale(base, new NoNegativeZero); }

}  // namespace railjoint
