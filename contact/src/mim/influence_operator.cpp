// FFT convolution of the half-space influence kernels (DC-FFT with zero padding), optionally with
// the local tangential compliance of an interfacial layer on the kernels' zero offset.
//
// References: Toumi (2016) eqs. (74)-(76), (117)-(120), annex B.3; Liu, Wang & Liu, Wear 243
// (2000) 101-111 (discrete convolution and FFT); Vollebregt, CONTACT user guide (interfacial
// layer as a local tangential compliance).
// Known deviations: the layer's normal compliance is not modelled (tangential only).

#include "ferro/contact/mim/influence_operator.hpp"

#include <fftw3.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <complex>
#include <cstring>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <vector>

#include "ferro/contact/mim/influence.hpp"

namespace ferro::contact::mim {
namespace {

// FFTW's planner is not thread-safe; serialise plan creation and destruction.
std::mutex& planner_mutex() {
  static std::mutex m;
  return m;
}

// Smallest size >= n whose only prime factors are 2, 3, 5 and 7 (fast FFTW sizes).
int fft_size(int n) {
  for (int m = n;; ++m) {
    int r = m;
    for (int f : {2, 3, 5, 7}) {
      while (r % f == 0) r /= f;
    }
    if (r == 1) return m;
  }
}

// Offset in elements represented by padded index m, or a sentinel when the index is not needed.
constexpr int kUnused = 1 << 30;
int offset_of(int m, int n, int padded) {
  if (m <= n - 1) return m;
  if (m >= padded - (n - 1)) return m - padded;
  return kUnused;
}

// fftw_malloc that reports failure (and size overflow) as an exception instead of returning
// a null pointer that the next write would dereference.
void* checked_fftw_malloc(std::size_t element_size, std::size_t count) {
  if (count > std::numeric_limits<std::size_t>::max() / element_size) {
    throw std::length_error(
        fmt::format("InfluenceOperator: a buffer of {} x {} bytes overflows", count, element_size));
  }
  void* p = fftw_malloc(element_size * count);
  if (p == nullptr) {
    throw std::runtime_error(
        fmt::format("InfluenceOperator: out of memory allocating {:.3g} MB for an FFT buffer",
                    static_cast<double>(element_size * count) / 1e6));
  }
  return p;
}

struct FftwBuffer {
  explicit FftwBuffer(std::size_t n) : size(n) {
    data = static_cast<double*>(checked_fftw_malloc(sizeof(double), n));
    std::fill(data, data + n, 0.0);
  }
  ~FftwBuffer() { fftw_free(data); }
  FftwBuffer(const FftwBuffer&) = delete;
  FftwBuffer& operator=(const FftwBuffer&) = delete;
  std::size_t size;
  double* data;
};

struct ComplexBuffer {
  explicit ComplexBuffer(std::size_t n) : size(n) {
    data = static_cast<fftw_complex*>(checked_fftw_malloc(sizeof(fftw_complex), n));
    std::memset(data, 0, sizeof(fftw_complex) * n);
  }
  ~ComplexBuffer() { fftw_free(data); }
  ComplexBuffer(const ComplexBuffer&) = delete;
  ComplexBuffer& operator=(const ComplexBuffer&) = delete;
  std::size_t size;
  fftw_complex* data;
};

using Spectrum = std::vector<std::complex<double>>;

}  // namespace

struct InfluenceOperator::Impl {
  Grid grid;
  CombinedMaterial material;
  double layer = 0.0;  // h / G3 [m/Pa]
  int px = 0;  // padded sizes
  int py = 0;
  std::size_t nreal = 0;
  std::size_t ncomplex = 0;
  FftwBuffer real_a;
  FftwBuffer real_b;
  ComplexBuffer spec_a;
  ComplexBuffer spec_b;
  ComplexBuffer spec_c;
  fftw_plan forward = nullptr;  // real_a -> spec_a, full 2-D (kernel set-up only)
  // Products: the inputs are zero beyond row ny - 1 and only rows < ny of the output are used,
  // so the 2-D transforms are split into 1-D passes that skip those rows (about a quarter less
  // work than full 2-D transforms, same result).
  fftw_plan rows_forward = nullptr;   // r2c along x on the ny data rows: real_a -> spec_a
  fftw_plan cols_forward = nullptr;   // c2c along y on all columns, in place on spec_a
  fftw_plan cols_backward = nullptr;  // c2c along y, in place on spec_c
  fftw_plan rows_backward = nullptr;  // c2r along x on the ny needed rows: spec_c -> real_a
  Spectrum kzz, kxx, kxy, kyy, dxx, dxy, dyx, dyy, ixx, ixy, iyy;
  double self_zz = 0.0, self_xx = 0.0, self_yy = 0.0, roll_self = 0.0;
  // Floor of the smaller eigenvalue of the inverted 2 x 2 symbol, relative to their mean.
  static constexpr double inverse_floor = 0.5;
  std::unique_ptr<InfluenceOperator> coarse;
  bool measure = false;

  Impl(const Grid& g, const CombinedMaterial& m, double layer_compliance, bool measure_plans)
      : grid(g),
        material(m),
        layer(layer_compliance),
        px(fft_size(2 * g.nx)),
        py(fft_size(2 * g.ny)),
        nreal(static_cast<std::size_t>(px) * static_cast<std::size_t>(py)),
        ncomplex(static_cast<std::size_t>(py) * static_cast<std::size_t>(px / 2 + 1)),
        real_a(nreal),
        real_b(nreal),
        spec_a(ncomplex),
        spec_b(ncomplex),
        spec_c(ncomplex) {
    const unsigned flags = (measure_plans ? FFTW_MEASURE : FFTW_ESTIMATE) | FFTW_DESTROY_INPUT;
    {
      std::lock_guard<std::mutex> lock(planner_mutex());
      forward = fftw_plan_dft_r2c_2d(py, px, real_a.data, spec_a.data,
                                     FFTW_ESTIMATE | FFTW_DESTROY_INPUT);
      const int nxc = px / 2 + 1;
      const int n_px[1] = {px};
      const int n_py[1] = {py};
      rows_forward = fftw_plan_many_dft_r2c(1, n_px, g.ny, real_a.data, nullptr, 1, px, spec_a.data,
                                            nullptr, 1, nxc, flags);
      cols_forward = fftw_plan_many_dft(1, n_py, nxc, spec_a.data, nullptr, nxc, 1, spec_a.data,
                                        nullptr, nxc, 1, FFTW_FORWARD, flags);
      cols_backward = fftw_plan_many_dft(1, n_py, nxc, spec_c.data, nullptr, nxc, 1, spec_c.data,
                                         nullptr, nxc, 1, FFTW_BACKWARD, flags);
      rows_backward = fftw_plan_many_dft_c2r(1, n_px, g.ny, spec_c.data, nullptr, 1, nxc,
                                             real_a.data, nullptr, 1, px, flags);
      if (!forward || !rows_forward || !cols_forward || !cols_backward || !rows_backward) {
        throw std::runtime_error("InfluenceOperator: FFTW could not create a plan");
      }
    }
    measure = measure_plans;
    build_kernels();
  }

  ~Impl() {
    std::lock_guard<std::mutex> lock(planner_mutex());
    for (fftw_plan p : {forward, rows_forward, cols_forward, cols_backward, rows_backward}) {
      if (p) fftw_destroy_plan(p);
    }
  }

  // Spectrum of a kernel k(ox, oy) placed at the cyclic offsets, scaled by 1/(px py) so that
  // the unnormalised inverse transform returns the convolution.
  template <class K>
  Spectrum kernel_spectrum(K&& k) {
    const double scale = 1.0 / static_cast<double>(nreal);
    for (int my = 0; my < py; ++my) {
      const int oy = offset_of(my, grid.ny, py);
      for (int mx = 0; mx < px; ++mx) {
        const int ox = offset_of(mx, grid.nx, px);
        double v = 0.0;
        if (ox != kUnused && oy != kUnused) v = k(ox, oy) * scale;
        real_a.data[static_cast<std::size_t>(my) * px + mx] = v;
      }
    }
    fftw_execute_dft_r2c(forward, real_a.data, spec_a.data);
    Spectrum s(ncomplex);
    for (std::size_t i = 0; i < ncomplex; ++i) s[i] = {spec_a.data[i][0], spec_a.data[i][1]};
    return s;
  }

  void build_kernels() {
    const double dx = grid.dx;
    const double dy = grid.dy;
    // Influence at every needed offset, including ox = nx for the shifted (rolling) kernel.
    const int wx = 2 * grid.nx + 1;
    const int wy = 2 * grid.ny - 1;
    std::vector<InfluenceCoefficients> table(static_cast<std::size_t>(wx) * wy);
    auto at = [&](int ox, int oy) -> const InfluenceCoefficients& {
      return table[static_cast<std::size_t>(oy + grid.ny - 1) * wx + (ox + grid.nx)];
    };
    for (int oy = -(grid.ny - 1); oy <= grid.ny - 1; ++oy) {
      for (int ox = -grid.nx; ox <= grid.nx; ++ox) {
        table[static_cast<std::size_t>(oy + grid.ny - 1) * wx + (ox + grid.nx)] =
            influence_coefficients(ox * dx, oy * dy, dx, dy, material);
      }
    }
    {  // interfacial layer: local tangential compliance on the element itself
      InfluenceCoefficients& self = table[static_cast<std::size_t>(grid.ny - 1) * wx + grid.nx];
      self.xx += layer;
      self.yy += layer;
    }
    self_zz = at(0, 0).zz;
    self_xx = at(0, 0).xx;
    self_yy = at(0, 0).yy;
    roll_self = (at(0, 0).xx - at(1, 0).xx) / dx;
    kzz = kernel_spectrum([&](int ox, int oy) { return at(ox, oy).zz; });
    kxx = kernel_spectrum([&](int ox, int oy) { return at(ox, oy).xx; });
    kxy = kernel_spectrum([&](int ox, int oy) { return at(ox, oy).xy; });
    kyy = kernel_spectrum([&](int ox, int oy) { return at(ox, oy).yy; });
    // Inverse of the 2 x 2 circulant symbol per frequency. The kernels are even (A^xy odd-odd),
    // so the symbols are real symmetric. For the continuous half-space the two eigenvalues are
    // in the ratio 1 - nu >= 0.5; the collocated operator is nearly singular at the y-Nyquist
    // frequency for nu ~ 0.28 (indefinite there above ~0.3), which would make the inverse blow
    // up, so the smaller eigenvalue is floored at a fraction of the mean of the two.
    {
      const double n2 = static_cast<double>(nreal) * static_cast<double>(nreal);
      ixx.assign(ncomplex, 0.0);
      ixy.assign(ncomplex, 0.0);
      iyy.assign(ncomplex, 0.0);
      for (std::size_t i = 0; i < ncomplex; ++i) {
        const double a = kxx[i].real(), b = kxy[i].real(), c = kyy[i].real();
        const double mean = 0.5 * (a + c), rad = std::hypot(0.5 * (a - c), b);
        const double floor = inverse_floor * std::abs(mean);
        const double l1 = std::max(mean + rad, floor), l2 = std::max(mean - rad, floor);
        // eigenvector of l1: angle theta with tan(2 theta) = 2 b / (a - c)
        const double theta = 0.5 * std::atan2(2.0 * b, a - c);
        const double co = std::cos(theta), si = std::sin(theta);
        ixx[i] = (co * co / l1 + si * si / l2) / n2;
        ixy[i] = (co * si / l1 - co * si / l2) / n2;
        iyy[i] = (si * si / l1 + co * co / l2) / n2;
      }
    }
    // Rolling: (A(X + h) - A(X)) / h with h = dx (eq. 117, 120).
    const double inv_h = 1.0 / dx;
    dxx = kernel_spectrum(
        [&](int ox, int oy) { return (at(ox + 1, oy).xx - at(ox, oy).xx) * inv_h; });
    dxy = kernel_spectrum(
        [&](int ox, int oy) { return (at(ox + 1, oy).xy - at(ox, oy).xy) * inv_h; });
    dyx = dxy;
    dyy = kernel_spectrum(
        [&](int ox, int oy) { return (at(ox + 1, oy).yy - at(ox, oy).yy) * inv_h; });
  }

  // Spectrum of a grid field (zero-padded): r2c on the data rows, zero rows above, columns.
  void transform(const double* field, double* real, fftw_complex* spec) {
    const std::size_t nxc = static_cast<std::size_t>(px) / 2 + 1;
    for (int iy = 0; iy < grid.ny; ++iy) {
      double* row = real + static_cast<std::size_t>(iy) * px;
      std::copy(field + static_cast<std::size_t>(iy) * grid.nx,
                field + static_cast<std::size_t>(iy + 1) * grid.nx, row);
      std::fill(row + grid.nx, row + px, 0.0);
    }
    fftw_execute_dft_r2c(rows_forward, real, spec);
    std::memset(spec + static_cast<std::size_t>(grid.ny) * nxc, 0,
                sizeof(fftw_complex) * static_cast<std::size_t>(py - grid.ny) * nxc);
    fftw_execute_dft(cols_forward, spec, spec);
  }
  // Grid field from a spectrum (destroys it): columns, then c2r on the needed rows only.
  void inverse(fftw_complex* spec, double* real, double* field) {
    fftw_execute_dft(cols_backward, spec, spec);
    fftw_execute_dft_c2r(rows_backward, spec, real);
    for (int iy = 0; iy < grid.ny; ++iy) {
      std::copy(real + static_cast<std::size_t>(iy) * px,
                real + static_cast<std::size_t>(iy) * px + grid.nx,
                field + static_cast<std::size_t>(iy) * grid.nx);
    }
  }

  void apply_scalar(const Spectrum& k, const double* in, double* out) {
    transform(in, real_a.data, spec_a.data);
    for (std::size_t i = 0; i < ncomplex; ++i) {  // explicit complex product (no NaN handling)
      const double kr = k[i].real(), ki = k[i].imag();
      const double ar = spec_a.data[i][0], ai = spec_a.data[i][1];
      spec_c.data[i][0] = kr * ar - ki * ai;
      spec_c.data[i][1] = kr * ai + ki * ar;
    }
    inverse(spec_c.data, real_a.data, out);
  }

  void apply_block(const Spectrum& kxx_, const Spectrum& kxy_, const Spectrum& kyx_,
                   const Spectrum& kyy_, const double* tx, const double* ty, double* ox,
                   double* oy) {
    transform(tx, real_a.data, spec_a.data);
    transform(ty, real_b.data, spec_b.data);
    // Both output spectra in one pass: c = Kxx a + Kxy b into spec_c, Kyx a + Kyy b into spec_b.
    for (std::size_t i = 0; i < ncomplex; ++i) {
      const double ar = spec_a.data[i][0], ai = spec_a.data[i][1];
      const double br = spec_b.data[i][0], bi = spec_b.data[i][1];
      const double k1r = kxx_[i].real(), k1i = kxx_[i].imag();
      const double k2r = kxy_[i].real(), k2i = kxy_[i].imag();
      const double k3r = kyx_[i].real(), k3i = kyx_[i].imag();
      const double k4r = kyy_[i].real(), k4i = kyy_[i].imag();
      spec_c.data[i][0] = k1r * ar - k1i * ai + k2r * br - k2i * bi;
      spec_c.data[i][1] = k1r * ai + k1i * ar + k2r * bi + k2i * br;
      spec_b.data[i][0] = k3r * ar - k3i * ai + k4r * br - k4i * bi;
      spec_b.data[i][1] = k3r * ai + k3i * ar + k4r * bi + k4i * br;
    }
    inverse(spec_c.data, real_a.data, ox);
    inverse(spec_b.data, real_b.data, oy);
  }
};

InfluenceOperator::InfluenceOperator(const Grid& grid, const CombinedMaterial& material,
                                     bool measure_plans)
    : InfluenceOperator(grid, material, 0.0, measure_plans) {}

InfluenceOperator::InfluenceOperator(const Grid& grid, const CombinedMaterial& material,
                                     double layer_compliance, bool measure_plans) {
  grid.validate("InfluenceOperator.grid");
  if (!(layer_compliance >= 0.0) || !std::isfinite(layer_compliance)) {
    throw std::invalid_argument(
        "InfluenceOperator.layer_compliance: must be finite and >= 0 m/Pa, got " +
        std::to_string(layer_compliance));
  }
  if (!(material.shear_modulus > 0.0) || !(material.poisson >= 0.0 && material.poisson < 0.5)) {
    throw std::invalid_argument(
        "InfluenceOperator.material: combined shear_modulus must be > 0 Pa and poisson in "
        "[0, 0.5)");
  }
  impl_ = std::make_unique<Impl>(grid, material, layer_compliance, measure_plans);
}

InfluenceOperator::~InfluenceOperator() = default;

const Grid& InfluenceOperator::grid() const {
  return impl_->grid;
}
const CombinedMaterial& InfluenceOperator::material() const {
  return impl_->material;
}

void InfluenceOperator::normal(const double* pressure, double* displacement_z) {
  impl_->apply_scalar(impl_->kzz, pressure, displacement_z);
}

void InfluenceOperator::tangential(const double* traction_x, const double* traction_y,
                                   double* displacement_x, double* displacement_y) {
  impl_->apply_block(impl_->kxx, impl_->kxy, impl_->kxy, impl_->kyy, traction_x, traction_y,
                     displacement_x, displacement_y);
}

void InfluenceOperator::rolling_difference(const double* traction_x, const double* traction_y,
                                           double* out_x, double* out_y) {
  impl_->apply_block(impl_->dxx, impl_->dxy, impl_->dyx, impl_->dyy, traction_x, traction_y, out_x,
                     out_y);
}

void InfluenceOperator::tangential_inverse(const double* in_x, const double* in_y, double* out_x,
                                           double* out_y) {
  impl_->apply_block(impl_->ixx, impl_->ixy, impl_->ixy, impl_->iyy, in_x, in_y, out_x, out_y);
}

InfluenceOperator& InfluenceOperator::coarse() {
  if (!impl_->coarse) {
    const Grid& f = impl_->grid;
    Grid c;
    c.nx = std::max(2, (f.nx + 1) / 2);
    c.ny = std::max(1, (f.ny + 1) / 2);
    c.dx = 2.0 * f.dx;
    c.dy = f.ny > 1 ? 2.0 * f.dy : f.dy;
    c.x0 = f.x0 + 0.5 * f.dx;
    c.y0 = f.ny > 1 ? f.y0 + 0.5 * f.dy : f.y0;
    impl_->coarse =
        std::make_unique<InfluenceOperator>(c, impl_->material, impl_->layer, impl_->measure);
  }
  return *impl_->coarse;
}

double InfluenceOperator::layer_compliance() const {
  return impl_->layer;
}

double InfluenceOperator::normal_self() const {
  return impl_->self_zz;
}
double InfluenceOperator::tangential_self_x() const {
  return impl_->self_xx;
}
double InfluenceOperator::tangential_self_y() const {
  return impl_->self_yy;
}
double InfluenceOperator::rolling_self() const {
  return impl_->roll_self;
}

}  // namespace ferro::contact::mim
