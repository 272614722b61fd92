// SPDX-License-Identifier: GPL-2.0-or-later
// cellmech-spectrum: amplitude spectrum of a sampled time series with FFTW, for the breathing
// validation (paper Appendix 2, Figs. 16-17).
//
//   cellmech-spectrum FILE TCOL YCOL [PAD]
//
// Reads columns TCOL (time) and YCOL (signal) of FILE (1-based; '#' lines skipped), assumes a
// uniform step, removes the mean, applies a Hann window, zero-pads to PAD times the length
// (default 8, a finer grid for locating peaks; it adds no resolution) and prints
// "omega amplitude" (angular frequency in radians per time unit of TCOL), then the local maxima
// as "# peak omega amplitude", the peak refined by a parabola through the three highest bins.
#include <fftw3.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

int main(int argc, char **argv)
{
  if (argc < 4) {
    std::fprintf(stderr, "usage: %s FILE TCOL YCOL [PAD]\n", argv[0]);
    return 2;
  }
  const int tcol = std::atoi(argv[2]), ycol = std::atoi(argv[3]);
  const int pad = argc > 4 ? std::atoi(argv[4]) : 8;
  if (tcol < 1 || ycol < 1 || pad < 1) {
    std::fprintf(stderr, "cellmech-spectrum: columns and PAD must be >= 1\n");
    return 2;
  }
  std::ifstream in(argv[1]);
  if (!in) {
    std::fprintf(stderr, "cellmech-spectrum: cannot read %s\n", argv[1]);
    return 2;
  }
  std::vector<double> t, y;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ss(line);
    std::vector<double> v;
    double x;
    while (ss >> x) v.push_back(x);
    if ((int) v.size() < std::max(tcol, ycol)) continue;
    t.push_back(v[tcol - 1]);
    y.push_back(v[ycol - 1]);
  }
  const int n = (int) y.size();
  if (n < 16) {
    std::fprintf(stderr, "cellmech-spectrum: only %d samples in %s\n", n, argv[1]);
    return 1;
  }
  const double dt = (t.back() - t.front()) / (n - 1);
  double mean = 0.0;
  for (double v : y) mean += v / n;

  const int N = n * pad;
  std::vector<double> buf(N, 0.0);
  for (int i = 0; i < n; i++) buf[i] = (y[i] - mean) * 0.5 * (1.0 - std::cos(2.0 * M_PI * i / (n - 1)));
  fftw_complex *out = fftw_alloc_complex(N / 2 + 1);
  fftw_plan plan = fftw_plan_dft_r2c_1d(N, buf.data(), out, FFTW_ESTIMATE);
  fftw_execute(plan);

  std::vector<double> amp(N / 2 + 1);
  const double domega = 2.0 * M_PI / (N * dt);
  for (int k = 0; k <= N / 2; k++) {
    amp[k] = std::hypot(out[k][0], out[k][1]) * 2.0 / n;
    std::printf("%.10g %.10g\n", k * domega, amp[k]);
  }
  for (int k = 1; k < N / 2; k++) {
    if (amp[k] > amp[k - 1] && amp[k] >= amp[k + 1]) {
      // vertex of the parabola through the three bins around the maximum
      const double a = amp[k - 1], b = amp[k], c = amp[k + 1];
      const double den = a - 2.0 * b + c;
      const double shift = den != 0.0 ? 0.5 * (a - c) / den : 0.0;
      std::printf("# peak %.10g %.10g\n", (k + shift) * domega, b - 0.25 * (a - c) * shift);
    }
  }
  fftw_destroy_plan(plan);
  fftw_free(out);
  return 0;
}
