#pragma once
/// @file number_format.hpp
/// Numbers as text: the library's one formatter, for messages, reports and CSV cells. Each
/// function is byte-identical to the printf conversion it names (C locale), without a
/// buffer to size: std::to_chars does the work.
///
///     covopt::FormatShortest(0.1 + 0.2);       // "0.30000000000000004" (reads back exactly)
///     covopt::FormatSignificant(1234567.0);    // "1.23457e+06" (printf's %g)
///     covopt::FormatSignificant(0.0180000001, 3);  // "0.018"  (%.3g)
///     covopt::FormatFixed(2.345e-3 * 1e3, 2);  // "2.35"   (%.2f)
///     covopt::FormatScientific(1e-8, 0);       // "1e-08"  (%.0e)

#include <string>

namespace covopt {

/// The shortest text that reads back as the same double (std::to_chars), e.g. "0.018",
/// "1e-05", "1e+20"; "inf", "-inf", and "nan" for every NaN.
std::string FormatShortest(double value);

/// printf's "%.<digits>g": `digits` significant digits (>= 1; 6 is printf's %g), trailing
/// zeros dropped, an exponent below 1e-4 and from 10^digits on; "inf", "-inf", "nan", "-nan".
std::string FormatSignificant(double value, int digits = 6);

/// printf's "%.<decimals>f": `decimals` (>= 0) digits after the point.
std::string FormatFixed(double value, int decimals);

/// printf's "%.<decimals>e": one digit, `decimals` (>= 0) more after the point, and a
/// two-digit (at least) exponent.
std::string FormatScientific(double value, int decimals);

}  // namespace covopt
