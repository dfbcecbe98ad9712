#!/usr/bin/env bash
# Installs covopt's build and test dependencies from Debian bookworm's packages.
# Idempotent: packages that are already installed are left alone, and apt is not
# touched at all when nothing is missing. Run as root (or with sudo available).
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libsundials-dev        # CVODES / ARKODE time integration, CVODES sensitivities
  libeigen3-dev          # small dense linear algebra
  libboost-math-dev      # optim: Φ, Φ⁻¹ and 1-D root/minimum searches (Boost.Math, header-only)
  catch2                 # unit tests (v2.13)
  libcli11-dev           # command-line parsing
  libtomlplusplus-dev    # scene and catalog files
  nlohmann-json3-dev     # --json output
  libssl-dev             # provenance: SHA-256 of every input file (OpenSSL libcrypto)
  libfmt-dev             # formatting
  libbenchmark-dev       # bench/ (Google Benchmark)
  gnuplot-nox            # --plot charts
  libnlopt-cxx-dev       # optimiser: global search (NLopt 2.7)
  coinor-libipopt-dev    # optimiser: local refinement (Ipopt 3.11+, pkg-config ipopt)
  pybind11-dev           # python/: the `import covopt` extension
  python3-dev            # Python 3 headers and library for the extension
  python3-numpy          # history and sweep arrays
  python3-pytest         # python/tests, run by CTest
  python3-matplotlib     # python/examples (charts)
  python3-distributed    # covopt.audit_many: a plant's programs audited in parallel on a dask cluster
  liborocos-kdl-dev      # robot/: Jacobian and joint-space inertia (Orocos KDL 1.5)
  liburdfdom-dev         # robot/: URDF parser (urdfdom 3.0)
  chromium               # --report FILE.pdf prints the HTML report with it (found at run time);
                         # tests: the browser check of every report (tests/report/check_reports.py)
  poppler-utils          # tests only: pdfinfo and pdftotext read the PDF reports back
  python3-pil            # tests only: the pixel statistics of the reports' screenshots (PIL)
  fonts-dejavu-core      # a font for Chromium and gnuplot to draw reports and charts with
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages already installed"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
