#include "covopt/chart/tornado_chart.hpp"

#include <fmt/format.h>

namespace covopt::chart {

std::string TornadoChart(const optim::ElasticityTable& table, ChartFormat format, const std::string& output_path) {
  const std::size_t n = table.rows.size();
  std::string script = GnuplotTerminal(format, 900,
                                       static_cast<int>(160 + 36 * n));
  script += fmt::format("set output {}\n", GnuplotQuoted(output_path));
  script += "set title 'Sensitivities: elasticity d ln r / d ln x of each injury ratio'\n";
  script += "set xlabel 'elasticity [-]'\nset grid xtics\nset key bottom right\nset xzeroaxis\n";
  script += fmt::format("set yrange [-0.7:{}]\n", static_cast<double>(n) - 0.3);
  std::string tics;
  for (std::size_t i = 0; i < n; ++i) {
    tics += fmt::format("{}{} {}", i == 0 ? "" : ", ", GnuplotQuoted(table.rows[i].field), n - 1 - i);
  }
  script += fmt::format("set ytics ({})\n", tics);
  script += "$D << EOD\n";
  for (std::size_t i = 0; i < n; ++i) {
    script += fmt::format("{} {:.9g} {:.9g}\n", n - 1 - i, table.rows[i].laceration, table.rows[i].contusion);
  }
  script += "EOD\n";
  script += "set style fill solid 0.75 border -1\n";
  script += "plot $D using ($2/2):($1+0.2):($2<0?$2:0):($2<0?0:$2):($1):($1+0.4) with boxxyerror lc rgb '#c0392b' "
            "title 'laceration ratio', \\\n"
            "     $D using ($3/2):($1-0.2):($3<0?$3:0):($3<0?0:$3):($1-0.4):($1) with boxxyerror lc rgb '#2e86c1' "
            "title 'contusion ratio'\n";
  return script;
}

}  // namespace covopt::chart
