// Reading (through the one CSV reader) and checking wheel/rail profiles.
//
// References: SIMPACK Rail-Wheel Profile format (.prw/.prr): keys inside spline.begin/end,
// points between point.begin/end, processing order 1..7 as numbered in the file header comments.
// Known deviations: approx.smooth, point.dist.min and point weights are ignored.

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>

#include "ferro/contact/geometry/profile.hpp"
#include "ferro/io/csv.hpp"

namespace ferro::contact {
namespace {

double parse_number(const std::string& text, const std::string& path, int line,
                    const std::string& what) {
  const std::optional<double> v = io::parse_number(text);
  if (v && std::isfinite(*v)) return *v;
  throw std::invalid_argument(
      fmt::format("{}:{}: cannot read {} from '{}' (expected a number)", path, line, what, text));
}

bool segments_intersect(double ay, double az, double by, double bz, double cy, double cz, double dy,
                        double dz) {
  auto orient = [](double py, double pz, double qy, double qz, double ry, double rz) {
    return (qy - py) * (rz - pz) - (qz - pz) * (ry - py);
  };
  const double o1 = orient(ay, az, by, bz, cy, cz);
  const double o2 = orient(ay, az, by, bz, dy, dz);
  const double o3 = orient(cy, cz, dy, dz, ay, az);
  const double o4 = orient(cy, cz, dy, dz, by, bz);
  return ((o1 > 0) != (o2 > 0)) && ((o3 > 0) != (o4 > 0)) && o1 != 0 && o2 != 0 && o3 != 0 &&
         o4 != 0;
}

}  // namespace

void check_profile(Profile& p) {
  const std::size_t n = p.size();
  if (n < 4 || p.z.size() != n) {
    throw std::invalid_argument(
        fmt::format("{}: a profile needs at least 4 points, got {}", p.source, n));
  }
  if (p.line.size() != n) p.line.assign(n, 0);
  // A polyline strictly monotone in y is the graph of a function and cannot cross itself, so
  // the O(n) monotonicity test settles valid profiles. Only a non-monotone profile is searched
  // for a crossing pair (a sharper diagnostic), pairwise and therefore only up to
  // kMaxPairwiseCheck points; larger ones get the monotonicity message directly.
  constexpr std::size_t kMaxPairwiseCheck = 4000;
  const bool decreasing = p.y.back() < p.y.front();
  std::size_t bad = 0;  // first index breaking strict monotonicity, 0 if none
  for (std::size_t i = 1; i < n && bad == 0; ++i) {
    if (!(decreasing ? p.y[i] < p.y[i - 1] : p.y[i] > p.y[i - 1])) bad = i;
  }
  if (bad != 0 && n <= kMaxPairwiseCheck) {
    for (std::size_t i = 0; i + 1 < n; ++i) {
      for (std::size_t j = i + 2; j + 1 < n; ++j) {
        if (segments_intersect(p.y[i], p.z[i], p.y[i + 1], p.z[i + 1], p.y[j], p.z[j], p.y[j + 1],
                               p.z[j + 1])) {
          throw std::invalid_argument(fmt::format(
              "{}:{}: profile is self-intersecting: segment at lines {}-{} crosses segment at "
              "lines {}-{}",
              p.source, p.line[j], p.line[i], p.line[i + 1], p.line[j], p.line[j + 1]));
        }
      }
    }
  }
  if (bad != 0) {
    throw std::invalid_argument(fmt::format(
        "{}:{}: profile is not monotone in y (y = {:.6f} mm after y = {:.6f} mm at line {}); "
        "the contact search needs a profile that is single-valued in y",
        p.source, p.line[bad], p.y[bad] * 1e3, p.y[bad - 1] * 1e3, p.line[bad - 1]));
  }
  // Order by increasing y (reverse a decreasing file).
  if (decreasing) {
    std::reverse(p.y.begin(), p.y.end());
    std::reverse(p.z.begin(), p.z.end());
    std::reverse(p.line.begin(), p.line.end());
  }
}

namespace {

// Every wheel or rail profile spans some 50-200 mm laterally. A span outside
// [kMinProfileSpan, kMaxProfileSpan] means a unit mistake (mm read as m or the reverse), which
// would otherwise surface far away as "no contact" or a conicity of 0.
constexpr double kMinProfileSpan = 5e-3;  // m
constexpr double kMaxProfileSpan = 1.0;   // m

void check_profile_scale(const Profile& p, const std::string& unit_hint) {
  const double span = p.y.back() - p.y.front();
  const auto [zmin, zmax] = std::minmax_element(p.z.begin(), p.z.end());
  if (span < kMinProfileSpan || span > kMaxProfileSpan || *zmax - *zmin > kMaxProfileSpan) {
    throw std::invalid_argument(fmt::format(
        "{}: implausible profile size: {:.6g} m wide and {:.6g} m high once read; a wheel or "
        "rail profile is {} mm to {} m wide. Check the length unit ({})",
        p.source, span, *zmax - *zmin, kMinProfileSpan * 1e3, kMaxProfileSpan, unit_hint));
  }
}

}  // namespace

Profile read_simpack_profile(const std::string& path) {
  io::CsvFormat format = io::CsvFormat::blanks();
  format.comment_marks = "!";
  format.trailing_comments = true;
  io::CsvReader file = io::CsvReader::open(path, format, "profile file");
  std::map<std::string, std::pair<std::string, int>> keys;
  std::vector<double> ys, zs;
  std::vector<int> lines;
  bool in_points = false, saw_points = false, saw_end = false, in_header = false;
  std::string s;
  while (file.next_line(s)) {
    const int line_no = file.line();
    if (s == "header.begin" || s == "header.end") {
      in_header = s == "header.begin";
      continue;
    }
    if (s == "point.begin") {
      in_points = true;
      saw_points = true;
      continue;
    }
    if (s == "point.end") {
      in_points = false;
      saw_end = true;
      continue;
    }
    if (in_points) {
      const std::vector<std::string> cols = io::split_cells(s, format);
      if (cols.size() < 2) {
        throw std::invalid_argument(fmt::format(
            "{}:{}: expected 'y z [weight]' in the point block, got '{}'", path, line_no, s));
      }
      ys.push_back(parse_number(cols[0], path, line_no, "y"));
      zs.push_back(parse_number(cols[1], path, line_no, "z"));
      lines.push_back(line_no);
      continue;
    }
    const auto eq = s.find('=');
    if (eq != std::string::npos) {
      std::string val(io::trim(std::string_view(s).substr(eq + 1)));
      if (val.size() >= 2 && val.front() == '\'') val = val.substr(1, val.size() - 2);
      // Header keys are prefixed: the spline block has its own "type" (data file type).
      keys[(in_header ? "header." : "") +
           std::string(io::trim(std::string_view(s).substr(0, eq)))] = {val, line_no};
    }
  }
  const int line_no = file.line();
  if (!saw_points || !saw_end) {
    throw std::invalid_argument(fmt::format(
        "{}:{}: not a SIMPACK profile: missing point.begin / point.end block", path, line_no));
  }
  auto num = [&](const std::string& key, double def) {
    const auto it = keys.find(key);
    if (it == keys.end()) return def;
    return parse_number(it->second.first, path, it->second.second, key);
  };
  Profile p;
  p.source = path;
  // Kind from the header (0 = rail, 1 = wheel), else from the extension (.prw = wheel).
  const double type = num("header.type", -1.0);
  const auto dot = path.find_last_of('.');
  const std::string ext = dot == std::string::npos ? "" : path.substr(dot);
  if (type == 0.0 || type == 1.0) {
    p.kind = type == 1.0 ? ProfileKind::wheel : ProfileKind::rail;
  } else {
    p.kind = (ext == ".prw" || ext == ".PRW") ? ProfileKind::wheel : ProfileKind::rail;
  }
  const double unit = num("units.len.f", 1000.0);  // l[user] / l[m]
  if (!(unit > 0.0)) {
    throw std::invalid_argument(
        fmt::format("{}: units.len.f must be positive, got {}", path, unit));
  }
  const double shift_y = num("shift.y", 0.0), shift_z = num("shift.z", 0.0);
  const double rot = num("rotate", 0.0) / num("units.ang.f", 1.0);
  const double bymin = num("bound.y.min", 1.0), bymax = num("bound.y.max", 0.0);
  const double bzmin = num("bound.z.min", 1.0), bzmax = num("bound.z.max", 0.0);
  const bool mirror_y = num("mirror.y", 0.0) != 0.0, mirror_z = num("mirror.z", 0.0) != 0.0;
  const bool inversion = num("inversion", 0.0) != 0.0;
  const double c = std::cos(rot), sn = std::sin(rot);
  for (std::size_t i = 0; i < ys.size(); ++i) {
    double y = ys[i] + shift_y, z = zs[i] + shift_z;        // 2: shift
    const double yr = c * y - sn * z, zr = sn * y + c * z;  // 3: rotate about x
    y = yr;
    z = zr;
    if (bymin < bymax && (y < bymin || y > bymax)) continue;  // 4: bounds
    if (bzmin < bzmax && (z < bzmin || z > bzmax)) continue;
    if (mirror_y) y = -y;  // 5: mirror
    if (mirror_z) z = -z;
    p.y.push_back(y / unit);  // 7: units
    p.z.push_back(z / unit);
    p.line.push_back(lines[i]);
  }
  if (inversion) {  // 6: order inversion
    std::reverse(p.y.begin(), p.y.end());
    std::reverse(p.z.begin(), p.z.end());
    std::reverse(p.line.begin(), p.line.end());
  }
  check_profile(p);
  check_profile_scale(p, fmt::format("units.len.f = {} user units per metre; 1000 for mm", unit));
  return p;
}

Profile read_two_column_profile(const std::string& path, ProfileKind kind) {
  io::CsvFormat format;
  format.separators = ",;\t";
  format.blank_separated = true;
  format.comment_marks = "#!%";
  format.header = false;
  io::CsvReader file = io::CsvReader::open(path, format, "profile file");
  Profile p;
  p.kind = kind;
  p.source = path;
  std::vector<std::string> cols;
  while (file.next(cols)) {
    const int line_no = file.line();
    if (cols.size() < 2) {
      throw std::invalid_argument(fmt::format("{}:{}: expected two columns 'y z' in mm, got '{}'",
                                              path, line_no, fmt::join(cols, " ")));
    }
    p.y.push_back(parse_number(cols[0], path, line_no, "y [mm]") * 1e-3);
    p.z.push_back(parse_number(cols[1], path, line_no, "z [mm]") * 1e-3);
    p.line.push_back(line_no);
  }
  check_profile(p);
  check_profile_scale(p, "two-column profile files are read in mm");
  return p;
}

Profile read_profile(const std::string& path, ProfileKind kind_if_plain) {
  const auto dot = path.find_last_of('.');
  const std::string ext = dot == std::string::npos ? "" : path.substr(dot);
  if (ext == ".prw" || ext == ".prr" || ext == ".PRW" || ext == ".PRR") {
    return read_simpack_profile(path);
  }
  return read_two_column_profile(path, kind_if_plain);
}

}  // namespace ferro::contact
