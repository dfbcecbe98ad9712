#pragma once
// Private: the time paths' state vectors, (q, δ') on the body-contact path ((q, δ', v_R, W)
// for a braking robot), (δ, δ', e) on the δ-only path and the extended path's seven entries,
// as SUNDIALS serial N_Vectors whose operations tables are replaced by kernels written for
// exactly that many entries.
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>

namespace covopt::internal {

/// A serial N_Vector of `length` entries, 2, 3, 4 or 7 (same content layout and vector ID as
/// N_VNew_Serial, so NV_DATA_S, the dense matrix and the dense linear solver work on it
/// unchanged) whose arithmetic operations are fixed-length kernels instead of the generic
/// serial loops. Clones copy the operations table, so every vector an integrator makes from it
/// uses the kernels too. Each kernel does the same floating-point operations in the same order
/// per entry as the serial implementation (including its special cases such as z = c (x + y)
/// for N_VLinearSum with a == b), so the integrators' results are the same to the bit.
/// Returns null for another length or when the allocation fails; free with N_VDestroy.
N_Vector MakeFixedLengthVector(int length, SUNContext context);

}  // namespace covopt::internal
