#pragma once
/// @file find_on_path.hpp
/// The search of $PATH for a program: gnuplot (the charts, covopt/chart/charts.hpp) and
/// Chromium (the PDF report, pdf_print.hpp) are found at run time, never linked.

#include <filesystem>
#include <optional>
#include <string_view>

namespace covopt::report {

/// The first executable file called `name` in the directories of $PATH (an empty entry is
/// the current directory).
std::optional<std::filesystem::path> FindOnPath(std::string_view name);

}  // namespace covopt::report
