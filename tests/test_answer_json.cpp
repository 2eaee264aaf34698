// answer_json.hpp, the one writer of answers, at every evidence level: each answer is one line of
// JSON that the general parser reads back member by member to the values it reports (the minimal
// verdict, the contact-only answer, the full classification), that nlohmann's writer would write
// byte for byte (the tree read from it dumps to the same text), and whose id is the caller's text
// byte for byte; the error line escapes any message, invalid UTF-8 replaced.
#include <catch2/catch.hpp>
#include <string>
#include <utility>

#include "io/answer_json.hpp"
#include "io/json_tree.hpp"
#include "io/margin_json.hpp"
#include "relpos/classify.hpp"
#include "relpos/contact.hpp"
#include "relpos/io.hpp"
#include "relpos/margin.hpp"

namespace {

using relpos::Rational;
using relpos::detail::io::Json;

relpos::Paraboloid cup() {
  return relpos::Paraboloid::standard({Rational(0), Rational(0), Rational(0)}, Rational(1), Rational(1));
}

relpos::Ellipsoid sphere(const Rational& z, const Rational& r) {
  return relpos::Ellipsoid::sphere({Rational(0), Rational(0), z}, r);
}

/// The answer read back: the writer's bytes are what dumping its tree gives, and the id comes first.
Json read_back(const std::string& text, const std::string& id) {
  const Json j = Json::parse(text);
  CHECK(relpos::detail::io::dump_json(j) == text);
  CHECK(text.rfind("{\"id\":" + id + ",", 0) == 0);
  return j;
}

}  // namespace

TEST_CASE("answers at every evidence level read back to what they report", "[answer_json]") {
  // Pairs in every position (E, I, TE, TI with a double root, C), ids of several JSON kinds.
  const std::pair<relpos::Ellipsoid, relpos::Position> cases[] = {
      {sphere(Rational(-3), Rational(1)), relpos::Position::E},
      {sphere(Rational(1), Rational(1, 10)), relpos::Position::I},
      {sphere(Rational(-1), Rational(1)), relpos::Position::TE},
      {sphere(Rational(1, 4), Rational(1, 4)), relpos::Position::TI},
      {sphere(Rational(0), Rational(1)), relpos::Position::C}};
  const std::string ids[] = {"7", "\"a \\\"quoted\\\" \xC3\xA9 id\"", "[1,{\"x\":null}]"};
  std::string out = "left over from the previous line";
  for (const auto& [e, position] : cases)
    for (const std::string& id : ids) {
      CAPTURE(id, relpos::to_string(position));
      const relpos::Verdict v = relpos::decide_position(e, cup());
      REQUIRE(v.position == position);
      relpos::detail::io::write_answer(id, out, v);
      Json j = read_back(out, id);
      CHECK(j.size() == 6);
      CHECK(j["position"] == relpos::to_string(v.position));
      CHECK(j["small"] == v.small);
      CHECK(j["contact"] == (relpos::contact_of(v.position) != relpos::Contact::None));
      CHECK(j["rule"] == relpos::describe(v.rule));
      CHECK(j["stage"] == relpos::to_string(v.stage));

      const relpos::ContactAnswer a = relpos::contact(e, cup());
      relpos::detail::io::write_answer(id, out, a);
      j = read_back(out, id);
      CHECK(j.size() == 5);
      CHECK(j["contact"] == relpos::to_string(a.contact));
      CHECK(j["position"] == relpos::to_string(a.position));
      CHECK(j["rule"] == relpos::describe(a.rule));
      CHECK(j["decided_by"] == relpos::decided_by(a.stage));
      const std::size_t members = ("{\"id\":" + id + ",").size();
      CHECK(relpos::io::contact_json_text(a) == "{" + out.substr(members));

      const relpos::Classification c = relpos::classify(e, cup(), relpos::Evidence::Full);
      relpos::io::RenderOptions options;
      options.digits = 20;
      relpos::detail::io::write_answer(id, out, c, options);
      j = read_back(out, id);
      CHECK(j["position"] == relpos::to_string(c.verdict.position));
      CHECK(j["certificate"].is_object());
      // Without an id: the same members.
      CHECK("{\"id\":" + id + "," + relpos::io::classification_json_text(c, options).substr(1) == out);
    }
}

TEST_CASE("the error line escapes any message and replaces invalid UTF-8", "[answer_json]") {
  const std::string messages[] = {"plain",
                                  "with \"quotes\" and \\ and a tab\t",
                                  "control \x01 and newline\n",
                                  "\xC3\xA9t\xC3\xA9",
                                  "invalid \xFF\xC3 bytes",
                                  ""};
  std::string out;
  for (const std::string& m : messages) {
    CAPTURE(m);
    REQUIRE(relpos::detail::io::write_error("42", m, out));
    const Json j = read_back(out, "42");
    CHECK(j.size() == 2);
    // What the tree of the message dumps to, invalid bytes replaced (U+FFFD).
    CHECK(relpos::detail::io::dump_json(j["error"]) == relpos::detail::io::dump_json(Json(m)));
  }
}

TEST_CASE("the margin is the last member of an answer at every evidence level", "[answer_json]") {
  // s* of spheres on the axis of z = x^2 + y^2 (math.md §14): the answer's other members are those
  // written without it, and the margin read back from the tree is the one written.
  const relpos::Ellipsoid spheres[] = {sphere(Rational(-3), Rational(1)), sphere(Rational(1), Rational(1, 10)),
                                       sphere(Rational(1, 4), Rational(1, 4))};
  for (const relpos::Ellipsoid& e : spheres) {
    const relpos::Margin m = relpos::margin(e, cup());
    REQUIRE(!relpos::verify_margin(e, cup(), m));
    std::string plain, with;
    auto check = [&](const std::string& level) {
      CAPTURE(level, with);
      const std::string id = "\"m\"";
      relpos::detail::io::append_margin_member(m, 12, with);
      Json j = read_back(with, id);
      CHECK((--j.end()).key() == "margin");
      const relpos::Margin back = relpos::detail::io::margin_from_tree(j["margin"]);
      CHECK(back.lo == m.lo);
      CHECK(back.hi == m.hi);
      CHECK(back.polynomial == m.polynomial);
      CHECK(back.approx == m.approx);
      CHECK(!relpos::verify_margin(e, cup(), back));
      j.erase("margin");
      CHECK(j == Json::parse(plain));
    };
    relpos::detail::io::write_answer("\"m\"", plain, relpos::decide_position(e, cup()));
    relpos::detail::io::write_answer("\"m\"", with, relpos::decide_position(e, cup()));
    check("minimal");
    relpos::detail::io::write_answer("\"m\"", plain, relpos::contact(e, cup()));
    relpos::detail::io::write_answer("\"m\"", with, relpos::contact(e, cup()));
    check("contact only");
    const relpos::Classification c = relpos::classify(e, cup(), relpos::Evidence::Full);
    relpos::detail::io::write_answer("\"m\"", plain, c, relpos::io::RenderOptions{});
    relpos::detail::io::write_answer("\"m\"", with, c, relpos::io::RenderOptions{});
    check("full");
  }
}
