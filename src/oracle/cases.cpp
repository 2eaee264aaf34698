// cases.hpp: the families' constructions, their doubles and the float code's matrices, each labelled
// by relpos (on the pool's threads), and their JSON lines.
#include "oracle/cases.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "base/worker_pool.hpp"
#include "oracle/json_text.hpp"
#include "oracle/nearest.hpp"
#include "relpos/classify.hpp"
#include "relpos/error.hpp"
#include "relpos/io.hpp"

namespace relpos::detail::oracle {

namespace {

std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) out.push_back(item);
  return out;
}

Ellipsoid ellipsoid_of(const Parameters& p) { return Ellipsoid::from_axes(p.centre, p.axes, p.e_rotation); }
Paraboloid paraboloid_of(const Parameters& p) { return Paraboloid::standard(p.vertex, p.a, p.b, p.p_rotation); }

/// The labels relpos gives the case's doubles: the parameters (never refused: a congruence of the
/// standard forms) and the matrices' upper triangles (refused when rounding broke the shape).
void label(Case& c) {
  const Parameters d = exact_parameters(c.doubles);
  const Ellipsoid de = ellipsoid_of(d), ee = ellipsoid_of(c.construction.exact);
  const Paraboloid dp = paraboloid_of(d), ep = paraboloid_of(c.construction.exact);
  c.double_position = decide_position(de, dp).position;
  c.exact_position = c.construction.position ? *c.construction.position : decide_position(ee, ep).position;
  try {  // every pair of the families has one; a pair beyond the size limit would have none
    c.margin = margin(ee, ep);
    c.double_margin = margin(de, dp);
  } catch (const InputError&) {
  }
  const char* role = "ellipsoid";
  try {
    const Ellipsoid e = Ellipsoid::from_doubles(upper_triangle(c.e_matrix));
    role = "paraboloid";
    const Paraboloid p = Paraboloid::from_doubles(upper_triangle(c.p_matrix));
    c.matrix_position = decide_position(e, p).position;
  } catch (const InputError& err) {
    c.matrix_error = std::string(role) + ": " + err.what();
  }
}

Json exact_json(const Rational& q) { return to_string(q); }
template <std::size_t N>
Json exact_json(const std::array<Rational, N>& x) {
  Json out = Json::array();
  for (const Rational& q : x) out.push_back(to_string(q));
  return out;
}
template <std::size_t N>
Json double_json(const std::array<double, N>& x) {
  Json out = Json::array();
  for (const double v : x) out.push_back(v);
  return out;
}
Json double_matrix_json(const DoubleMatrix4& m) {
  Json out = Json::array();
  for (std::size_t i = 0; i < 4; ++i) out.push_back(Json::array({m[4 * i], m[4 * i + 1], m[4 * i + 2], m[4 * i + 3]}));
  return out;
}

Json exact_ellipsoid(const Parameters& p) {
  return Json{{"center", exact_json(p.centre)}, {"axes", exact_json(p.axes)}, {"rotation", exact_json(p.e_rotation)}};
}
Json exact_paraboloid(const Parameters& p) {
  return Json{{"vertex", exact_json(p.vertex)},
              {"a", exact_json(p.a)},
              {"b", exact_json(p.b)},
              {"rotation", exact_json(p.p_rotation)}};
}
Json double_ellipsoid(const DoubleParameters& d) {
  return Json{
      {"center", double_json(d.centre)}, {"axes", double_json(d.axes)}, {"rotation", double_json(d.e_rotation)}};
}
Json double_paraboloid(const DoubleParameters& d) {
  return Json{{"vertex", double_json(d.vertex)}, {"a", d.a}, {"b", d.b}, {"rotation", double_json(d.p_rotation)}};
}

/// A margin's JSON value (doc/certificates.md, "Margins"), as `relpos batch --margin` writes it.
Json margin_json(const Margin& m) { return Json::parse(io::margin_json_text(m)); }

}  // namespace

namespace {

std::vector<const Family*> chosen_families(const std::vector<std::string>& names) {
  std::vector<const Family*> chosen;
  for (const std::string& name : names) {
    if (name == "all") {
      for (const Family& f : families()) chosen.push_back(&f);
      continue;
    }
    const Family* f = find_family(name);
    if (!f) {
      std::string known;
      for (const Family& g : families()) known += std::string(known.empty() ? "" : ", ") + g.name;
      throw InputError("unknown family '" + name + "' (the families: " + known + ", all)");
    }
    chosen.push_back(f);
  }
  return chosen;
}

Rational eps_of(const std::string& text) {
  Rational e;
  try {
    e = parse_rational(text);
  } catch (const InputError& err) {
    throw InputError("--eps: " + std::string(err.what()));
  }
  if (e < 0 || e >= 1) throw InputError("--eps: each eps must lie in [0, 1), got " + text);
  return e;
}

/// The n cases of family f at one eps, not yet constructed.
void add_cases(std::vector<Case>& out, const Family* f, const std::string& eps_text, const Rational& eps,
               std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    Case c;
    c.family = f;
    c.eps_text = eps_text;
    c.eps = eps;
    c.index = i;
    c.id = std::string(f->name) + "/" + eps_text + "/" + std::to_string(i);
    out.push_back(std::move(c));
  }
}

}  // namespace

std::vector<Case> make_cases(const CaseOptions& options) {
  const std::vector<std::string> eps_texts = options.eps.empty() ? split(kDefaultEps) : options.eps;
  std::vector<Rational> eps;
  for (const std::string& t : eps_texts) eps.push_back(eps_of(t));
  std::vector<Case> out;
  for (const Family* f : chosen_families(options.families)) {
    if (!f->uses_eps) {  // made once, at eps = 0, whatever the epsilons
      add_cases(out, f, "0", Rational(0), options.n);
      continue;
    }
    for (std::size_t k = 0; k < eps.size(); ++k) add_cases(out, f, eps_texts[k], eps[k], options.n);
  }
  // Construct and label on the pool (a classification or three per case).
  const unsigned threads = options.threads ? options.threads : std::max(1u, std::thread::hardware_concurrency());
  detail::WorkerPool pool(threads);
  std::vector<std::string> errors(out.size());
  pool.run(out.size(), [&](std::size_t i) {
    Case& c = out[i];
    try {
      c.construction = construct(*c.family, c.eps, options.seed, c.index);
      c.doubles = nearest_parameters(c.construction.exact);
      c.e_matrix = ellipsoid_matrix(c.doubles);
      c.p_matrix = paraboloid_matrix(c.doubles);
      label(c);
    } catch (const std::exception& err) {
      errors[i] = c.id + ": " + err.what();
    }
  });
  for (const std::string& e : errors)
    if (!e.empty()) throw InputError(e);
  return out;
}

std::string case_line(const Case& c, Form form) {
  Json line;
  line["id"] = c.id;
  if (form == Form::Exact) {
    line["ellipsoid"] = exact_ellipsoid(c.construction.exact);
    line["paraboloid"] = exact_paraboloid(c.construction.exact);
  } else if (form == Form::Double) {
    line["ellipsoid"] = double_ellipsoid(c.doubles);
    line["paraboloid"] = double_paraboloid(c.doubles);
  } else {
    line["ellipsoid"] = double_matrix_json(upper_triangle(c.e_matrix));
    line["paraboloid"] = double_matrix_json(upper_triangle(c.p_matrix));
  }
  Json meta;
  meta["family"] = c.family->name;
  meta["eps"] = c.eps_text;
  meta["index"] = c.index;
  meta["side"] = c.construction.side.empty() ? Json(nullptr) : Json(c.construction.side);
  meta["position"] = to_string(c.exact_position);
  meta["by"] = c.construction.position ? "construction" : "relpos";
  meta["double_position"] = to_string(c.double_position);
  meta["matrix_position"] = c.matrix_position ? Json(to_string(*c.matrix_position)) : Json(nullptr);
  if (!c.matrix_position) meta["matrix_error"] = c.matrix_error;
  if (c.margin) meta["margin"] = margin_json(*c.margin);
  if (c.double_margin) meta["double_margin"] = margin_json(*c.double_margin);
  meta["double"] = Json{{"ellipsoid", double_ellipsoid(c.doubles)},
                        {"paraboloid", double_paraboloid(c.doubles)},
                        {"E", double_matrix_json(c.e_matrix)},
                        {"P", double_matrix_json(c.p_matrix)}};
  line["meta"] = std::move(meta);
  return line.dump(-1, ' ', false, Json::error_handler_t::replace);
}

}  // namespace relpos::detail::oracle
