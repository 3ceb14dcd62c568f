// The assessment's HDF5 file (layout in docs/OUTPUT.md, "Assessment").
#include <fmt/format.h>

#include <cmath>
#include <string>

#include "ferro/io/hdf5.hpp"
#include "ferro/scenarios/analysis/assessment.hpp"
#include "ferro/scenarios/run.hpp"

namespace ferro::scenarios::analysis {

namespace {

std::string number(double v) { return std::isnan(v) ? "nan" : fmt::format("{:.9g}", v); }

}  // namespace

void write_assessment(const Assessment& a, const std::string& source, const std::string& path) {
  io::H5File file = io::H5File::create(path);
  file.set_attribute("/", "program", std::string("ferrodyn"));
  file.set_attribute("/", "created_utc", utc_timestamp());
  file.set_attribute("/", "kind", std::string("assessment"));
  file.set_attribute("/", "source", source);
  file.set_attribute("/", "vehicle", a.vehicle);
  file.set_attribute("/", "category", a.category);
  file.set_attribute("/", "alpha", a.alpha);
  file.set_attribute("/", "mu", a.mu);
  file.set_attribute("/", "sample_rate", a.sample_rate);
  file.set_attribute("/", "f0", a.f0);
  file.set_attribute("/", "f0_from_spectrum", a.f0_from_spectrum ? 1 : 0);
  file.set_attribute("/", "twist_test", a.twist_test ? 1 : 0);
  file.set_attribute("/", "accelerations_derived", a.accelerations_derived ? 1 : 0);
  std::string notes;
  for (const auto& n : a.notes) notes += n + "\n";
  file.set_attribute("/", "notes", notes);
  file.set_attribute("/", "pass", std::string(a.pass ? "yes" : "no"));

  std::string table =
      "group\tquantity\titem\tsection\tunit\tvalue\tlimit\tverdict\tmax_abs\tposition\t"
      "p_0.15\tp_50\tp_99.85\trms\tsamples\n";
  std::vector<double> value, limit, max_abs, position, p_low, p_median, p_high, rms, verdict;
  for (const auto& r : a.rows) {
    table += fmt::format("{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}\n", r.group,
                         r.quantity, r.item, r.section, r.unit, number(r.value), number(r.limit),
                         to_string(r.verdict), number(r.max_abs), number(r.position),
                         number(r.stats.p_low), number(r.stats.p_median), number(r.stats.p_high),
                         number(r.stats.rms), r.stats.samples);
    value.push_back(r.value);
    limit.push_back(r.limit);
    max_abs.push_back(r.max_abs);
    position.push_back(r.position);
    p_low.push_back(r.stats.p_low);
    p_median.push_back(r.stats.p_median);
    p_high.push_back(r.stats.p_high);
    rms.push_back(r.stats.rms);
    verdict.push_back(r.verdict == Verdict::pass ? 1.0 : r.verdict == Verdict::fail ? 0.0 : NAN);
  }
  file.write_text("/assessment/table", table);
  file.write_vector("/assessment/rows/value", value, "SI (table's unit column)",
                    "statistic compared with the limit, one per table row");
  file.write_vector("/assessment/rows/limit", limit, "SI", "limit (NaN: none)");
  file.write_vector("/assessment/rows/verdict", verdict, "-", "1 pass, 0 fail, NaN information");
  file.write_vector("/assessment/rows/max_abs", max_abs, "SI", "largest |value| in the section");
  file.write_vector("/assessment/rows/position", position, "m",
                    "where the largest |value| is, at the wheel / axle / body concerned");
  file.write_vector("/assessment/rows/p_low", p_low, "SI", "0.15 % percentile");
  file.write_vector("/assessment/rows/p_median", p_median, "SI", "50 % percentile");
  file.write_vector("/assessment/rows/p_high", p_high, "SI", "99.85 % percentile");
  file.write_vector("/assessment/rows/rms", rms, "SI", "root mean square in the section");

  std::string names;
  std::vector<double> start, end, radius;
  for (const auto& s : a.sections) {
    names += s.name + "\n";
    start.push_back(s.start);
    end.push_back(s.end);
    radius.push_back(s.radius);
  }
  file.write_text("/assessment/sections/names", names);
  file.write_vector("/assessment/sections/start", start, "m", "section start");
  file.write_vector("/assessment/sections/end", end, "m", "section end");
  file.write_vector("/assessment/sections/radius", radius, "m", "curve radius (0: none)");

  for (std::size_t k = 0; k < a.signals.size(); ++k) {
    const auto& s = a.signals[k];
    const std::string g = fmt::format("/assessment/signals/{:03d}", k);
    file.write_vector(g + "/position", s.position, "m", "at the item concerned");
    file.write_vector(g + "/value", s.value, s.unit, s.description);
    file.set_attribute(g, "quantity", s.quantity);
    file.set_attribute(g, "item", s.item);
    file.set_attribute(g, "unit", s.unit);
    file.set_attribute(g, "limit", s.limit);
  }
  file.set_attribute("/", "status", std::string("completed"));
}

}  // namespace ferro::scenarios::analysis
