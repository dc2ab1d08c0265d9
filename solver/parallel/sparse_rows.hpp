// SPDX-License-Identifier: MIT
// Sparse rows of a nodal sum (ContactRegion::exchange_rows): a message carries only the rows with a
// nonzero bit, each as its position in the list and `width` values, and the receiver applies it
// to every listed row in list order, +0.0 for a row the message leaves out. Adding +0.0 anywhere
// in a sum gives the same bits as adding it where the dense exchange did (a sum is -0.0 only if
// every term is), and a row left out is +0.0 bits (-0.0 travels), so sparse and dense agree exactly.
#pragma once

namespace tribex::solver::parallel {

/// Writes the rows values[nodes[j]][0..width) with a nonzero bit (NaN and -0.0 included) as
/// (j, the width values) to `message`, j ascending; returns the number of doubles written, at most
/// (width + 1) * count.
int pack_nonzero_rows(const double* values, int width, const int* nodes, int count, double* message);

/// For j = 0..count-1: values[nodes[j]] += (add) or = (assign) the message's row j, or +0.0 where the
/// message (length doubles, from pack_nonzero_rows) has none.
void apply_rows(const double* message, int length, int width, const int* nodes, int count, double* values, bool add);

}  // namespace tribex::solver::parallel
