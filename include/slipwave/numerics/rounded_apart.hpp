// A value rounded on its own, whatever the code around it. The project compiles with FMA
// contraction (GCC's default, -ffp-contract=fast), which fuses a product into a later sum
// only where the product has no other use, and differently in each inlined copy of the same
// source: one expression may then round differently from one caller to the next. A product
// passed through roundedApart is rounded as a product in every copy, so that every copy gives
// the same bits (a restart, a re-evaluation and the first evaluation must agree).
#pragma once

namespace slipwave::numerics {

template <class T>
inline T roundedApart(T x) {
#ifdef __SSE2__
  asm("" : "+x"(x));
#else
  asm("" : "+m"(x));
#endif
  return x;
}

} // namespace slipwave::numerics
