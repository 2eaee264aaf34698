// relpos._relpos._cases and _judge: the case families and the judge of `relpos cases` and `relpos
// judge` (src/oracle/), for relpos.testing (doc/oracle.md): one implementation, bound.
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <vector>

#include "module.hpp"
#include "oracle/cases.hpp"
#include "oracle/chart.hpp"
#include "oracle/judge.hpp"

namespace relpos_python {

using namespace pybind11::literals;

namespace {

relpos::detail::oracle::Form form_of(const std::string& form) {
  if (form == "exact") return relpos::detail::oracle::Form::Exact;
  if (form == "double") return relpos::detail::oracle::Form::Double;
  if (form == "matrix") return relpos::detail::oracle::Form::Matrix;
  throw relpos::InputError("form: expected 'exact', 'double' or 'matrix', got '" + form + "'");
}

relpos::detail::oracle::Truth truth_of(const std::string& truth) {
  if (truth == "exact") return relpos::detail::oracle::Truth::Exact;
  if (truth == "double") return relpos::detail::oracle::Truth::Double;
  if (truth == "matrix") return relpos::detail::oracle::Truth::Matrix;
  throw relpos::InputError("truth: expected 'exact', 'double' or 'matrix', got '" + truth + "'");
}

}  // namespace

void bind_oracle(py::module_& m) {
  py::list names;
  for (const auto& f : relpos::detail::oracle::families()) names.append(py::make_tuple(f.name, f.description));
  m.attr("_FAMILIES") = py::tuple(names);
  m.attr("_DEFAULT_EPS") = relpos::detail::oracle::kDefaultEps;
  m.def(
      "_cases",
      [](const std::vector<std::string>& families, std::size_t n, const std::vector<std::string>& eps,
         unsigned long long seed, unsigned threads, const std::string& form) {
        relpos::detail::oracle::CaseOptions options;
        options.families = families;
        options.n = n;
        options.eps = eps;
        options.seed = seed;
        options.threads = threads;
        const relpos::detail::oracle::Form f = form_of(form);
        std::string out;
        {
          py::gil_scoped_release release;
          for (const auto& c : relpos::detail::oracle::make_cases(options))
            out.append(relpos::detail::oracle::case_line(c, f)) += '\n';
        }
        return out;
      },
      "families"_a, "n"_a, "eps"_a, "seed"_a, "threads"_a, "form"_a,
      "The lines of `relpos cases FAMILIES --n N --eps EPS --seed SEED --form FORM`, as one text.");
  m.def(
      "_judge",
      [](const std::string& cases, const std::string& answers, const std::string& truth,
         std::optional<std::string> tolerance, const std::vector<std::string>& by, bool baselines, bool chart) {
        relpos::detail::oracle::JudgeOptions options;
        options.truth = truth_of(truth);
        if (tolerance) {
          options.tolerance = relpos::parse_rational(*tolerance);
          if (*options.tolerance < 0) throw relpos::InputError("tolerance: must be at least 0, got " + *tolerance);
        }
        if (!by.empty()) options.by = by;
        options.baselines = baselines;
        std::string json, md, csv, png;
        {
          py::gil_scoped_release release;
          const relpos::detail::oracle::JudgeReport r = relpos::detail::oracle::judge(cases, answers, options);
          json = relpos::detail::oracle::report_json(r);
          md = relpos::detail::oracle::report_markdown(r);
          csv = relpos::detail::oracle::report_csv(r);
          if (chart) png = relpos::detail::oracle::chart_png(r);
        }
        return py::make_tuple(json, md, csv, chart ? py::object(py::bytes(png)) : py::object(py::none()));
      },
      "cases"_a, "answers"_a, "truth"_a, "tolerance"_a, "by"_a, "baselines"_a, "chart"_a,
      "`relpos judge` on the texts: (JSON report, Markdown, CSV, the chart's PNG bytes or None).");
}

}  // namespace relpos_python
