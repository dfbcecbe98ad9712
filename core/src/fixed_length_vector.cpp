// The time paths' state vectors: SUNDIALS' serial N_Vector with fixed-length kernels in its
// operations table (see fixed_length_vector.hpp), for the body-contact time path's 2 entries,
// the δ-only path's 3 and the extended path's 7.
//
// Why: the generic serial kernels loop over a run-time length and, in the fused operations,
// over the vectors first; for a few entries the loop set-up dominates (the profile of the
// default time path had N_VLinearCombination_Serial alone at about a fifth of the time, of the
// extended path at about a third). Per entry, every kernel below does the serial kernel's
// operations in the serial kernel's order, so the results are identical.
#include "fixed_length_vector.hpp"

#include <cmath>

namespace covopt::internal {
namespace {

inline double* Data(N_Vector v) { return static_cast<N_VectorContent_Serial>(v->content)->data; }

template <int kLength>
void LinearSum(double a, N_Vector x, double b, N_Vector y, N_Vector z) {
  const double* xd = Data(x);
  const double* yd = Data(y);
  double* zd = Data(z);
  // The serial kernel's special cases, where they round differently from a x + b y: with a
  // or b equal to ±1 its special forms (x + y, c x + y, c x - y, ...) equal a x + b y exactly.
  const bool unit = a == 1.0 || b == 1.0 || a == -1.0 || b == -1.0;
  if (!unit && a == b) {
    for (int i = 0; i < kLength; ++i) zd[i] = a * (xd[i] + yd[i]);
    return;
  }
  if (!unit && a == -b) {
    for (int i = 0; i < kLength; ++i) zd[i] = a * (xd[i] - yd[i]);
    return;
  }
  for (int i = 0; i < kLength; ++i) zd[i] = (a * xd[i]) + (b * yd[i]);
}

template <int kLength>
void Const(double c, N_Vector z) {
  double* zd = Data(z);
  for (int i = 0; i < kLength; ++i) zd[i] = c;
}

template <int kLength>
void Prod(N_Vector x, N_Vector y, N_Vector z) {
  const double* xd = Data(x);
  const double* yd = Data(y);
  double* zd = Data(z);
  for (int i = 0; i < kLength; ++i) zd[i] = xd[i] * yd[i];
}

template <int kLength>
void Div(N_Vector x, N_Vector y, N_Vector z) {
  const double* xd = Data(x);
  const double* yd = Data(y);
  double* zd = Data(z);
  for (int i = 0; i < kLength; ++i) zd[i] = xd[i] / yd[i];
}

template <int kLength>
void Scale(double c, N_Vector x, N_Vector z) {  // c x: exact copies/negations for c = ±1
  const double* xd = Data(x);
  double* zd = Data(z);
  for (int i = 0; i < kLength; ++i) zd[i] = c * xd[i];
}

template <int kLength>
void Abs(N_Vector x, N_Vector z) {
  const double* xd = Data(x);
  double* zd = Data(z);
  for (int i = 0; i < kLength; ++i) zd[i] = std::abs(xd[i]);
}

template <int kLength>
void Inv(N_Vector x, N_Vector z) {
  const double* xd = Data(x);
  double* zd = Data(z);
  for (int i = 0; i < kLength; ++i) zd[i] = 1.0 / xd[i];
}

template <int kLength>
void AddConst(N_Vector x, double b, N_Vector z) {
  const double* xd = Data(x);
  double* zd = Data(z);
  for (int i = 0; i < kLength; ++i) zd[i] = xd[i] + b;
}

template <int kLength>
double DotProd(N_Vector x, N_Vector y) {
  const double* xd = Data(x);
  const double* yd = Data(y);
  double sum = 0.0;
  for (int i = 0; i < kLength; ++i) sum += xd[i] * yd[i];
  return sum;
}

template <int kLength>
double MaxNorm(N_Vector x) {
  const double* xd = Data(x);
  double max = 0.0;
  for (int i = 0; i < kLength; ++i) {
    if (std::abs(xd[i]) > max) max = std::abs(xd[i]);
  }
  return max;
}

template <int kLength>
double WeightedSquareSum(N_Vector x, N_Vector w) {
  const double* xd = Data(x);
  const double* wd = Data(w);
  double sum = 0.0;
  for (int i = 0; i < kLength; ++i) {
    const double product = xd[i] * wd[i];
    sum += product * product;
  }
  return sum;
}

template <int kLength>
double WrmsNorm(N_Vector x, N_Vector w) {
  return std::sqrt(WeightedSquareSum<kLength>(x, w) / static_cast<double>(kLength));
}

template <int kLength>
double Min(N_Vector x) {
  const double* xd = Data(x);
  double min = xd[0];
  for (int i = 1; i < kLength; ++i) {
    if (xd[i] < min) min = xd[i];
  }
  return min;
}

template <int kLength>
void Compare(double c, N_Vector x, N_Vector z) {
  const double* xd = Data(x);
  double* zd = Data(z);
  for (int i = 0; i < kLength; ++i) zd[i] = std::abs(xd[i]) >= c ? 1.0 : 0.0;
}

template <int kLength>
sunbooleantype InvTest(N_Vector x, N_Vector z) {
  const double* xd = Data(x);
  double* zd = Data(z);
  sunbooleantype no_zero_found = SUNTRUE;
  for (int i = 0; i < kLength; ++i) {
    if (xd[i] == 0.0) {
      no_zero_found = SUNFALSE;
    } else {
      zd[i] = 1.0 / xd[i];
    }
  }
  return no_zero_found;
}

/// z = Σ c_k X_k. Entry by entry, in the serial kernel's order (its cases z == X_0 with
/// c_0 = 1, z == X_0, and z separate); an entry only ever reads the same entry of the
/// others, so the entry-outer loop gives the serial kernel's results even under aliasing.
template <int kLength>
int LinearCombination(int count, double* c, N_Vector* X, N_Vector z) {
  if (count < 1) return -1;
  if (count == 1) {
    Scale<kLength>(c[0], X[0], z);
    return 0;
  }
  if (count == 2) {
    LinearSum<kLength>(c[0], X[0], c[1], X[1], z);
    return 0;
  }
  double* zd = Data(z);
  const bool in_place = X[0] == z;
  constexpr int kCached = 16;  // the largest tables (Fehlberg 13 stages) ask for 14
  const double* xd[kCached];
  if (count > kCached) {
    for (int i = 0; i < kLength; ++i) {
      if (!in_place) {
        zd[i] = c[0] * Data(X[0])[i];
      } else if (c[0] != 1.0) {
        zd[i] *= c[0];
      }
      for (int k = 1; k < count; ++k) zd[i] += c[k] * Data(X[k])[i];
    }
    return 0;
  }
  bool aliased = false;  // z is also one of X_1 .. X_(count-1)
  for (int k = 0; k < count; ++k) {
    xd[k] = Data(X[k]);
    aliased = aliased || (k > 0 && X[k] == z);
  }
  if (!aliased) {  // the sums in registers, each in the serial kernel's order
    const bool scale_first = in_place && c[0] != 1.0;
    double sum[kLength];
    for (int i = 0; i < kLength; ++i) sum[i] = in_place ? zd[i] : c[0] * xd[0][i];
    if (scale_first) {
      for (int i = 0; i < kLength; ++i) sum[i] *= c[0];
    }
    for (int k = 1; k < count; ++k) {
      for (int i = 0; i < kLength; ++i) sum[i] += c[k] * xd[k][i];
    }
    for (int i = 0; i < kLength; ++i) zd[i] = sum[i];
    return 0;
  }
  for (int i = 0; i < kLength; ++i) {
    if (!in_place) {
      zd[i] = c[0] * xd[0][i];
    } else if (c[0] != 1.0) {
      zd[i] *= c[0];
    }
    for (int k = 1; k < count; ++k) zd[i] += c[k] * xd[k][i];
  }
  return 0;
}

/// Z_k = a_k x + Y_k.
template <int kLength>
int ScaleAddMulti(int count, double* a, N_Vector x, N_Vector* Y, N_Vector* Z) {
  if (count < 1) return -1;
  if (count == 1) {
    LinearSum<kLength>(a[0], x, 1.0, Y[0], Z[0]);
    return 0;
  }
  const double* xd = Data(x);
  if (Y == Z) {
    for (int k = 0; k < count; ++k) {
      double* yd = Data(Y[k]);
      for (int i = 0; i < kLength; ++i) yd[i] += a[k] * xd[i];
    }
    return 0;
  }
  for (int k = 0; k < count; ++k) {
    const double* yd = Data(Y[k]);
    double* zd = Data(Z[k]);
    for (int i = 0; i < kLength; ++i) zd[i] = a[k] * xd[i] + yd[i];
  }
  return 0;
}

template <int kLength>
int DotProdMulti(int count, N_Vector x, N_Vector* Y, double* products) {
  if (count < 1) return -1;
  for (int k = 0; k < count; ++k) products[k] = DotProd<kLength>(x, Y[k]);
  return 0;
}

template <int kLength>
void SetFixedLengthKernels(N_Vector_Ops ops) {
  ops->nvlinearsum = LinearSum<kLength>;
  ops->nvconst = Const<kLength>;
  ops->nvprod = Prod<kLength>;
  ops->nvdiv = Div<kLength>;
  ops->nvscale = Scale<kLength>;
  ops->nvabs = Abs<kLength>;
  ops->nvinv = Inv<kLength>;
  ops->nvaddconst = AddConst<kLength>;
  ops->nvdotprod = DotProd<kLength>;
  ops->nvmaxnorm = MaxNorm<kLength>;
  ops->nvwrmsnorm = WrmsNorm<kLength>;
  ops->nvmin = Min<kLength>;
  ops->nvcompare = Compare<kLength>;
  ops->nvinvtest = InvTest<kLength>;
  ops->nvlinearcombination = LinearCombination<kLength>;
  ops->nvscaleaddmulti = ScaleAddMulti<kLength>;
  ops->nvdotprodmulti = DotProdMulti<kLength>;
  ops->nvdotprodlocal = DotProd<kLength>;
  ops->nvmaxnormlocal = MaxNorm<kLength>;
  ops->nvminlocal = Min<kLength>;
  ops->nvinvtestlocal = InvTest<kLength>;
  ops->nvwsqrsumlocal = WeightedSquareSum<kLength>;
}

}  // namespace

N_Vector MakeFixedLengthVector(int length, SUNContext context) {
  if (length != 2 && length != 3 && length != 4 && length != 7) return nullptr;
  N_Vector v = N_VNew_Serial(length, context);
  if (!v) return nullptr;
  // The serial vector's fused and vector-array operations (used by CVODE's Adams history
  // updates and ARKODE's stage sums); those not replaced below stay the serial ones.
  N_VEnableFusedOps_Serial(v, SUNTRUE);
  if (length == 2) {
    SetFixedLengthKernels<2>(v->ops);
  } else if (length == 3) {
    SetFixedLengthKernels<3>(v->ops);
  } else if (length == 4) {
    SetFixedLengthKernels<4>(v->ops);
  } else {
    SetFixedLengthKernels<7>(v->ops);
  }
  return v;
}

}  // namespace covopt::internal
