#pragma once
// Forward and back substitution with a CHOLMOD supernodal LLᵀ factor, supernode by supernode as CHOLMOD's
// own solve with one right-hand side, in double or single precision, over the leading columns only if
// asked (CholeskySchurLU eliminates the last block otherwise). A supernode's columns k1 … k2−1 list their
// rows in `rows` (the first k2 − k1 of them its diagonal block) and store their entries column by column
// with those rows as the leading dimension.
#include <cholmod.h>

#include <vector>

namespace tirefem {

template <class T>
struct SupernodalFactorView {
  int n = 0, supernodes = 0;
  const int* permutation = nullptr;  // L's row k is A's row permutation[k]
  const int* first_column = nullptr;  // supernodes + 1
  const int* row_start = nullptr;     // supernodes + 1
  const int* value_start = nullptr;   // supernodes + 1
  const int* rows = nullptr;
  const T* values = nullptr;
};

// A view of CHOLMOD's factor L (supernodal, LLᵀ, real, int indices); n = 0 for any other.
SupernodalFactorView<double> view_of(const cholmod_factor& L);

// y ← L⁻¹ y over columns [0, end): the rows of y at and beyond `end` receive the updates L_21 y_1.
// `below`: scratch, grown as needed (a supernode straddling `end` has more rows below its columns used
// than below its diagonal block).
template <class T>
void forward_substitute(const SupernodalFactorView<T>& f, T* y, std::vector<T>& below, int end);
// y_1 ← L_11⁻ᵀ (y_1 − L_21ᵀ y_2) over columns [0, end), with y_2 (rows ≥ end) given.
template <class T>
void back_substitute(const SupernodalFactorView<T>& f, T* y, std::vector<T>& below, int end);

}  // namespace tirefem
