// The time path's 3-entry state vector: SUNDIALS' serial N_Vector with fixed-length kernels
// in its operations table (see three_state_vector.hpp).
//
// Why: the generic serial kernels loop over a run-time length and, in the fused operations,
// over the vectors first; for three entries the loop set-up dominates (the profile of the
// default time path had N_VLinearCombination_Serial alone at about a fifth of the time).
// Per entry, every kernel below does the serial kernel's operations in the serial kernel's
// order, so the results are identical.
#include "three_state_vector.hpp"

#include <cmath>

namespace covopt::internal {
namespace {

constexpr int kLength = 3;

inline double* Data(N_Vector v) { return static_cast<N_VectorContent_Serial>(v->content)->data; }

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

void Const(double c, N_Vector z) {
  double* zd = Data(z);
  for (int i = 0; i < kLength; ++i) zd[i] = c;
}

void Prod(N_Vector x, N_Vector y, N_Vector z) {
  const double* xd = Data(x);
  const double* yd = Data(y);
  double* zd = Data(z);
  for (int i = 0; i < kLength; ++i) zd[i] = xd[i] * yd[i];
}

void Div(N_Vector x, N_Vector y, N_Vector z) {
  const double* xd = Data(x);
  const double* yd = Data(y);
  double* zd = Data(z);
  for (int i = 0; i < kLength; ++i) zd[i] = xd[i] / yd[i];
}

void Scale(double c, N_Vector x, N_Vector z) {  // c x: exact copies/negations for c = ±1
  const double* xd = Data(x);
  double* zd = Data(z);
  for (int i = 0; i < kLength; ++i) zd[i] = c * xd[i];
}

void Abs(N_Vector x, N_Vector z) {
  const double* xd = Data(x);
  double* zd = Data(z);
  for (int i = 0; i < kLength; ++i) zd[i] = std::abs(xd[i]);
}

void Inv(N_Vector x, N_Vector z) {
  const double* xd = Data(x);
  double* zd = Data(z);
  for (int i = 0; i < kLength; ++i) zd[i] = 1.0 / xd[i];
}

void AddConst(N_Vector x, double b, N_Vector z) {
  const double* xd = Data(x);
  double* zd = Data(z);
  for (int i = 0; i < kLength; ++i) zd[i] = xd[i] + b;
}

double DotProd(N_Vector x, N_Vector y) {
  const double* xd = Data(x);
  const double* yd = Data(y);
  double sum = 0.0;
  for (int i = 0; i < kLength; ++i) sum += xd[i] * yd[i];
  return sum;
}

double MaxNorm(N_Vector x) {
  const double* xd = Data(x);
  double max = 0.0;
  for (int i = 0; i < kLength; ++i) {
    if (std::abs(xd[i]) > max) max = std::abs(xd[i]);
  }
  return max;
}

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

double WrmsNorm(N_Vector x, N_Vector w) {
  return std::sqrt(WeightedSquareSum(x, w) / static_cast<double>(kLength));
}

double Min(N_Vector x) {
  const double* xd = Data(x);
  double min = xd[0];
  for (int i = 1; i < kLength; ++i) {
    if (xd[i] < min) min = xd[i];
  }
  return min;
}

void Compare(double c, N_Vector x, N_Vector z) {
  const double* xd = Data(x);
  double* zd = Data(z);
  for (int i = 0; i < kLength; ++i) zd[i] = std::abs(xd[i]) >= c ? 1.0 : 0.0;
}

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
int LinearCombination(int count, double* c, N_Vector* X, N_Vector z) {
  if (count < 1) return -1;
  if (count == 1) {
    Scale(c[0], X[0], z);
    return 0;
  }
  if (count == 2) {
    LinearSum(c[0], X[0], c[1], X[1], z);
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
  if (!aliased) {  // the three sums in registers, each in the serial kernel's order
    const bool scale_first = in_place && c[0] != 1.0;
    double z0 = in_place ? zd[0] : c[0] * xd[0][0];
    double z1 = in_place ? zd[1] : c[0] * xd[0][1];
    double z2 = in_place ? zd[2] : c[0] * xd[0][2];
    if (scale_first) {
      z0 *= c[0];
      z1 *= c[0];
      z2 *= c[0];
    }
    for (int k = 1; k < count; ++k) {
      z0 += c[k] * xd[k][0];
      z1 += c[k] * xd[k][1];
      z2 += c[k] * xd[k][2];
    }
    zd[0] = z0;
    zd[1] = z1;
    zd[2] = z2;
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
int ScaleAddMulti(int count, double* a, N_Vector x, N_Vector* Y, N_Vector* Z) {
  if (count < 1) return -1;
  if (count == 1) {
    LinearSum(a[0], x, 1.0, Y[0], Z[0]);
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

int DotProdMulti(int count, N_Vector x, N_Vector* Y, double* products) {
  if (count < 1) return -1;
  for (int k = 0; k < count; ++k) products[k] = DotProd(x, Y[k]);
  return 0;
}

}  // namespace

N_Vector MakeThreeStateVector(SUNContext context) {
  N_Vector v = N_VNew_Serial(kLength, context);
  if (!v) return nullptr;
  // The serial vector's fused and vector-array operations (used by CVODE's Adams history
  // updates and ARKODE's stage sums); those not replaced below stay the serial ones.
  N_VEnableFusedOps_Serial(v, SUNTRUE);
  N_Vector_Ops ops = v->ops;
  ops->nvlinearsum = LinearSum;
  ops->nvconst = Const;
  ops->nvprod = Prod;
  ops->nvdiv = Div;
  ops->nvscale = Scale;
  ops->nvabs = Abs;
  ops->nvinv = Inv;
  ops->nvaddconst = AddConst;
  ops->nvdotprod = DotProd;
  ops->nvmaxnorm = MaxNorm;
  ops->nvwrmsnorm = WrmsNorm;
  ops->nvmin = Min;
  ops->nvcompare = Compare;
  ops->nvinvtest = InvTest;
  ops->nvlinearcombination = LinearCombination;
  ops->nvscaleaddmulti = ScaleAddMulti;
  ops->nvdotprodmulti = DotProdMulti;
  ops->nvdotprodlocal = DotProd;
  ops->nvmaxnormlocal = MaxNorm;
  ops->nvminlocal = Min;
  ops->nvinvtestlocal = InvTest;
  ops->nvwsqrsumlocal = WeightedSquareSum;
  return v;
}

}  // namespace covopt::internal
