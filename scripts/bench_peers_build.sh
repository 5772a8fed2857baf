#!/usr/bin/env bash
# Builds the peer tools of scripts/bench_peers.sh from their public sources, outside the
# repository (issue 18), and prints the commands to give it.
#
#   scripts/bench_peers_build.sh --imu-tk-src DIR --allantools-src DIR [--out DIR]
#
# --imu-tk-src   a checkout of imu_tk (github.com/Kyle-ak/imu_tk): its accelerometer calibration
#                is built against Debian's Ceres (libceres-dev, with libgoogle-glog-dev and
#                libgflags-dev) with g++ -O3, driven by a small program of ours, written here, that
#                runs MultiPosCalibration::calibrateAcc with the settings of imu_tk's
#                apps/test_imu_calib.cpp for its Xsens data (init static 50 s, g = 9.81744,
#                initial bias 32768, verbose output off). imu_tk's plotting (gnuplot, Qt) is only
#                used with verbose output: it is replaced by empty functions. Two setters of its
#                calibration.h are declared to return a value and fall off their end, undefined
#                behaviour that GCC 12 at -O2 turns into a crash: the copy built here returns it.
#                Nothing else of imu_tk is changed.
# --allantools-src  a checkout of allantools (github.com/aewallin/allantools), run by Debian's
#                python3 with python3-numpy and python3-scipy: a driver of ours loads the file with
#                numpy.loadtxt and runs allantools.oadev (frequency data) per axis at accelcal's
#                averaging factors (every octave plus 10 per decade, up to N/4).
# --out          where to build (default ${TMPDIR:-/tmp}/accelcal-peers); never inside the repo.
#
# Then: scripts/bench_peers.sh --peers OUT (or the two commands this prints).
set -euo pipefail

repo=$(cd "$(dirname "$0")/.." && pwd)
imu_tk_src='' allantools_src='' out=${TMPDIR:-/tmp}/accelcal-peers
die() { echo "bench_peers_build: $*" >&2; exit 2; }
while (($#)); do
  case $1 in
    -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    --imu-tk-src|--allantools-src|--out)
      (($# >= 2)) || die "$1 needs a value (--help)"
      case $1 in
        --imu-tk-src) imu_tk_src=$2 ;;
        --allantools-src) allantools_src=$2 ;;
        --out) out=$2 ;;
      esac
      shift 2 ;;
    *) die "unknown option $1 (--help)" ;;
  esac
done
[[ -n $imu_tk_src || -n $allantools_src ]] || die "give --imu-tk-src DIR and/or --allantools-src DIR (--help)"
mkdir -p "$out"
out=$(cd "$out" && pwd)
[[ $out != "$repo" && $out != "$repo"/* ]] || die "--out must be outside the repository ($repo)"

if [[ -n $imu_tk_src ]]; then
  [[ -f $imu_tk_src/include/imu_tk/calibration.h && -f $imu_tk_src/src/calibration.cpp ]] ||
    die "$imu_tk_src is not an imu_tk checkout (no include/imu_tk/calibration.h)"
  [[ -f /usr/include/ceres/ceres.h ]] ||
    die "Ceres is missing: apt-get install libceres-dev (it brings glog, gflags and Eigen)"
  d=$out/imu_tk
  rm -rf "$d" && mkdir -p "$d/include/imu_tk"
  cp "$imu_tk_src"/include/imu_tk/*.h "$d/include/imu_tk/"
  sed -i 's/{ init_interval_duration_ = duration; }/{ init_interval_duration_ = duration; return duration; }/;
          s/{ interval_n_samples_ = num; }/{ interval_n_samples_ = num; return num; }/' \
    "$d/include/imu_tk/calibration.h"
  cat >"$d/imu_tk_acc.cpp" <<'EOF'
// imu_tk's accelerometer calibration alone, on the file given as the last argument.
#include <iostream>
#include "imu_tk/calibration.h"
#include "imu_tk/io_utils.h"
int main(int argc, char** argv) {
  if (argc < 2) return 2;
  std::vector<imu_tk::TriadData> acc;
  imu_tk::importAsciiData(argv[argc - 1], acc, imu_tk::TIMESTAMP_UNIT_SEC);
  imu_tk::CalibratedTriad init;
  init.setBias(Eigen::Vector3d(32768, 32768, 32768));
  imu_tk::MultiPosCalibration calib;
  calib.setInitStaticIntervalDuration(50.0);
  calib.setInitAccCalibration(init);
  calib.setGravityMagnitude(9.81744);
  calib.enableVerboseOutput(false);
  calib.enableAccUseMeans(false);
  const bool ok = calib.calibrateAcc(acc);
  std::cout << calib.getAccCalib() << std::endl;
  return ok ? 0 : 1;
}
EOF
  cat >"$d/no_plots.cpp" <<'EOF'
// imu_tk plots (gnuplot) only with verbose output, which the driver turns off.
#include "imu_tk/visualization.h"
namespace imu_tk {
Plot::Plot() {}
template <typename T>
void Plot::plotIntervals(const std::vector<TriadData_<T>>&, const std::vector<DataInterval>&, DataInterval) {}
template void Plot::plotIntervals<double>(const std::vector<TriadData_<double>>&,
                                          const std::vector<DataInterval>&, DataInterval);
template void Plot::plotIntervals<float>(const std::vector<TriadData_<float>>&,
                                         const std::vector<DataInterval>&, DataInterval);
void waitForKey() {}
}  // namespace imu_tk
EOF
  echo "building imu_tk's accelerometer calibration in $d (about a minute) ..."
  g++ -O3 -DNDEBUG -std=c++17 -w -I"$d/include" -I/usr/include/eigen3 \
    "$imu_tk_src/src/calibration.cpp" "$imu_tk_src/src/io_utils.cpp" "$imu_tk_src/src/filters.cpp" \
    "$d/imu_tk_acc.cpp" "$d/no_plots.cpp" -o "$d/imu_tk_acc" -lceres -lglog -lgflags -lpthread
fi

if [[ -n $allantools_src ]]; then
  [[ -f $allantools_src/allantools/allantools.py ]] ||
    die "$allantools_src is not an allantools checkout (no allantools/allantools.py)"
  /usr/bin/python3 -c 'import numpy, scipy' 2>/dev/null ||
    die "Debian's numpy and scipy are missing: apt-get install python3-numpy python3-scipy"
  d=$out/allantools
  rm -rf "$d" && mkdir -p "$d"
  cp -r "$allantools_src/allantools" "$d/"
  cat >"$d/oadev_axes.py" <<'EOF'
"""allantools.oadev per axis of a text recording `t ax ay az ...`.
Usage: python3 oadev_axes.py FILE RATE_HZ AXES   (AXES "1" or "1,2,3": columns after t)"""
import os
import sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import numpy as np
import allantools

path, rate, axes = sys.argv[1], float(sys.argv[2]), [int(a) for a in sys.argv[3].split(",")]
data = np.loadtxt(path, comments="#", usecols=axes, ndmin=2)
n = data.shape[0]
factors = {2 ** k for k in range(64) if 2 ** k <= n // 4}
k = 0
while round(10 ** (k / 10.0)) <= n // 4:
    factors.add(int(round(10 ** (k / 10.0))))
    k += 1
taus = np.array(sorted(factors), dtype=float) / rate
for j in range(data.shape[1]):
    t, ad, ade, ns = allantools.oadev(data[:, j], rate=rate, data_type="freq", taus=taus)
    print(axes[j], len(t), ad[0], ad[-1])
EOF
fi

echo "built in $out; run:"
echo "  scripts/bench_peers.sh --peers $out"
[[ -x $out/imu_tk/imu_tk_acc ]] && echo "  (imu_tk: $out/imu_tk/imu_tk_acc FILE)"
[[ -f $out/allantools/oadev_axes.py ]] && echo "  (allantools: /usr/bin/python3 $out/allantools/oadev_axes.py FILE RATE AXES)"
exit 0
