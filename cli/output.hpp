#pragma once
/// @file output.hpp
/// What `covopt simulate` prints and writes: the readable table, the JSON object, the
/// history CSV, and an atomic file writer. Physics comes from covopt::core only; this file
/// formats it.

#include <filesystem>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "covopt/core/impact_model.hpp"
#include "covopt/core/impact_result.hpp"
#include "covopt/core/scene.hpp"
#include "covopt/core/time_integration.hpp"
#include "covopt/report/csv.hpp"
#include "covopt/report/history_csv.hpp"
#include "covopt/report/output_file.hpp"
#include "covopt/report/scene_headline.hpp"
#include "covopt/report/simulation_json.hpp"
#include "covopt/report/simulation_text.hpp"

namespace covopt::cli {

/// One finished computation with everything needed to report it (covopt::report's, whose
/// SimulationJson is the --json object).
using report::SimulationReport;

/// The scene in one short line, and its inputs beyond that line (report/scene_headline.hpp).
using report::SceneDetailsBeyondHeadline;
using report::SceneHeadline;

/// The readable report: scene, peaks, verdicts, method and solver, warnings (report/simulation_text.hpp).
using report::PrintTable;

/// The history CSV (covopt/report/history_csv.hpp).
using report::HistoryCsv;
using report::kHistoryCsvExtendedColumns;
using report::kHistoryCsvHeader;

/// One CSV field, by covopt's one CSV rule (covopt/report/csv.hpp, RFC 4180).
using report::CsvField;

/// The one file writer every file the CLI writes goes through (covopt/report/output_file.hpp).
using report::FileIdentity;
using report::IdentifyFile;
using report::OutputFile;
using report::RegisterTemporaryFile;
using report::UnregisterTemporaryFile;
using report::WriteFileAtomically;

}  // namespace covopt::cli
