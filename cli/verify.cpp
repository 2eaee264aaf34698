// relpos verify INPUT.jsonl ANSWERS.jsonl [--numbers exact|double] [--quiet]: checks every
// certificate of a `relpos batch` output against its input with the independent verifier
// (include/relpos/position.hpp), and the margin of an answer that has one
// (include/relpos/margin.hpp). An answer's "numbers" member says how its input was read
// (`relpos batch --numbers double` writes "double"); --numbers is the reading of answers without it.
//
// Line N of ANSWERS answers line N of INPUT. An answer with "error" is skipped when its input line is
// not a valid pair, and counted as unanswered when it is. Prints `line N: <reason>` per failure
// (unless --quiet) and `verified N, failed N, skipped N[, unanswered N]`.
// Exit: 0 iff nothing failed and nothing valid was left unanswered, 1 otherwise, 2 on usage errors
// (unknown option, missing or unreadable file).
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <exception>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "commands.hpp"
#include "common.hpp"
#include "io/batch.hpp"
#include "io/certificate_json.hpp"
#include "io/general_io.hpp"
#include "io/json_tree.hpp"
#include "io/margin_json.hpp"
#include "relpos/classify.hpp"
#include "relpos/error.hpp"
#include "relpos/io.hpp"
#include "relpos/margin.hpp"

namespace {

using relpos::detail::io::Json;

constexpr const char* kVerifyHelp =
    "Usage: relpos verify INPUT.jsonl ANSWERS.jsonl [--numbers exact|double] [--quiet]\n"
    "\n"
    "Check the certificate of every answer of `relpos batch INPUT.jsonl > ANSWERS.jsonl` with an\n"
    "independent verifier that uses exact rational arithmetic only (no code of the classifier), and\n"
    "the \"margin\" of an answer that has one (`relpos batch --margin`).\n"
    "Line N of ANSWERS must answer line N of INPUT. Answers with \"error\" are skipped when the input\n"
    "line is not a valid pair, and counted as unanswered when it is.\n"
    "The input line is read as the answer's \"numbers\" member says (`relpos batch --numbers double`\n"
    "writes \"numbers\": \"double\": each JSON number is the double nearest its text); an answer without\n"
    "it is read as --numbers says (default exact).\n"
    "Prints 'line N: reason' for each failure (not with --quiet) and a summary line.\n"
    "Exit: 0 all verified, 1 a failure or an unanswered valid pair, 2 usage error.\n";

std::optional<relpos::Position> position_from_text(const std::string& s) {
  if (s == "I") return relpos::Position::I;
  if (s == "TI") return relpos::Position::TI;
  if (s == "C") return relpos::Position::C;
  if (s == "TE") return relpos::Position::TE;
  if (s == "E") return relpos::Position::E;
  return std::nullopt;
}

/// A value or message echoed in a reason, shortened when long: its start, an ellipsis and its length
/// (a 100 000-digit number is not printed whole).
std::string clip(const std::string& text) {
  constexpr std::size_t kKeep = 100;
  if (text.size() <= kKeep + 40) return text;
  std::size_t cut = kKeep;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) >> 6) == 2) --cut;  // not inside a UTF-8 sequence
  return text.substr(0, cut) + "... (" + std::to_string(text.size()) + " characters)";
}

/// A line holding nothing but blanks.
bool blank(const std::string& line) { return line.find_first_not_of(" \t\r") == std::string::npos; }

struct InputPair {
  std::optional<relpos::Ellipsoid> e;
  std::optional<relpos::Paraboloid> p;
  std::optional<relpos::Quadric> q;  // a general quadric in place of the paraboloid (doc/quadrics.md)
  Json id;
  std::string error;  // why the line is not a valid pair (empty if it is)
};

/// The input line as `relpos batch` reads it (relpos::detail::io::read_batch_line), its numbers exact or
/// the doubles nearest their text.
InputPair read_input(const std::string& line, long number, bool doubles) {
  InputPair in;
  relpos::detail::io::BatchLine read;
  relpos::detail::io::BatchOptions options;
  options.numbers_as_doubles = doubles;
  try {
    relpos::detail::io::read_batch_line(line, number, options, nullptr, read);
    in.e = std::move(read.ellipsoid);
    in.p = std::move(read.paraboloid);
    in.q = std::move(read.quadric);
  } catch (const std::exception& err) {
    in.error = err.what();
  }
  try {
    in.id = Json::parse(read.id);  // as `relpos batch` echoes it
  } catch (const std::exception&) {
    in.id = nullptr;  // not comparable (a number beyond double range)
  }
  return in;
}

/// Why the answer's "margin" (when it has one) does not prove s* for the pair (relpos/margin.hpp).
std::optional<std::string> margin_failure(const relpos::Ellipsoid& e, const relpos::Paraboloid& p, const Json& answer) {
  if (!answer.contains("margin")) return std::nullopt;
  return relpos::verify_margin(e, p, relpos::detail::io::margin_from_tree(answer["margin"]));
}

}  // namespace

namespace relpos_cli {

void print_verify_help(std::ostream& os) { os << kVerifyHelp; }

int run_verify(Args& args) {
  std::vector<std::string> files;
  bool quiet = false, doubles = false;
  while (!args.done()) {
    std::string v;
    if (args.help()) {
      print_verify_help(std::cout);
      return finish_cout();
    } else if (args.flag("--quiet") || args.flag("-q")) {
      quiet = true;
    } else if (args.value("--numbers", v)) {
      if (v != "exact" && v != "double") throw UsageError{"--numbers must be exact or double, got '" + v + "'"};
      doubles = v == "double";
    } else if (args.peek().size() > 1 && args.peek()[0] == '-') {
      args.unexpected();
    } else {
      files.push_back(args.next());
    }
  }
  if (files.size() != 2) throw UsageError{"expected INPUT.jsonl and ANSWERS.jsonl"};
  for (const std::string& file : files) {  // both readable files before anything is printed
    const int fd = file == "-" ? -1 : open_input(file);
    if (fd < 0) {
      if (file == "-") std::cerr << "relpos: verify reads two files, not standard input\n";
      return 2;
    }
    ::close(fd);
  }
  std::ifstream input(files[0], std::ios::binary), answers(files[1], std::ios::binary);
  long verified = 0, failed = 0, skipped = 0, unanswered = 0, number = 0;
  auto fail = [&](long n, const std::string& reason) {
    ++failed;
    if (!quiet) std::cout << "line " << n << ": " << reason << "\n";
  };
  std::string in_line, answer_line;
  for (;;) {
    const bool has_in = static_cast<bool>(std::getline(input, in_line));
    const bool has_answer = static_cast<bool>(std::getline(answers, answer_line));
    if (!has_in && !has_answer) break;
    ++number;
    if ((!has_in && blank(answer_line)) || (!has_answer && blank(in_line))) continue;  // a trailing blank line
    if (!has_in) {
      fail(number, "an answer line without an input line (the files have different numbers of lines)");
      continue;
    }
    if (!has_answer) {
      fail(number, "no answer line (the files have different numbers of lines)");
      continue;
    }
    Json answer;
    try {
      answer = relpos::detail::io::parse_json_exact(answer_line);
    } catch (const std::exception& err) {
      fail(number, std::string("the answer is not JSON: ") + clip(err.what()));
      continue;
    }
    if (!answer.is_object()) {
      fail(number, "the answer is not a JSON object");
      continue;
    }
    bool read_doubles = doubles;  // the answer's own number mode first
    if (answer.contains("numbers")) {
      const Json& mode = answer["numbers"];
      if (!mode.is_string() || (mode != "exact" && mode != "double")) {
        fail(number, "\"numbers\" is " + clip(mode.dump()) + ", not \"exact\" or \"double\"");
        continue;
      }
      read_doubles = mode == "double";
    }
    const InputPair in = read_input(in_line, number, read_doubles);
    if (!in.id.is_null() && answer.contains("id")) {
      Json answer_id;
      try {
        answer_id = Json::parse(answer_line)["id"];
      } catch (const std::exception&) {
        answer_id = in.id;  // not comparable
      }
      if (answer_id != in.id) {
        fail(number, "the answer's id " + clip(answer_id.dump()) + " is not the input's " + clip(in.id.dump()));
        continue;
      }
    }
    if (answer.contains("error")) {
      if (in.e) {
        ++unanswered;
        if (!quiet)
          std::cout << "line " << number << ": unanswered: the input is a valid pair but the answer is an error ("
                    << clip(answer["error"].dump()) << ")\n";
      } else {
        ++skipped;
      }
      continue;
    }
    if (!in.e) {
      fail(number, "the input is not a valid pair (" + clip(in.error) + ") but the answer is not an error");
      continue;
    }
    if (!answer.contains("position") || !answer["position"].is_string()) {
      fail(number, "the answer has no \"position\"");
      continue;
    }
    const std::string position_text = answer["position"].get<std::string>();
    if (in.q) {  // a general pair: its positions and certificates (src/io/general_io.hpp)
      const std::optional<relpos::QuadricPosition> qp = relpos::detail::io::quadric_position_from_text(position_text);
      if (!qp) {
        fail(number, "position \"" + clip(position_text) + "\" is not one of I, TI, C, TE, E, O, TO, EQ");
      } else if (!answer.contains("certificate")) {
        fail(number, "the answer has no \"certificate\"");
      } else {
        try {
          const relpos::QuadricCertificate c = relpos::detail::io::quadric_certificate_from_json(answer["certificate"]);
          if (auto reason = relpos::verify_certificate(*in.e, *in.q, *qp, c))
            fail(number, position_text + ": " + clip(*reason));
          else
            ++verified;
        } catch (const std::exception& err) {
          fail(number, position_text + ": " + clip(err.what()));
        }
      }
      continue;
    }
    const std::optional<relpos::Position> position = position_from_text(position_text);
    if (!position) {
      fail(number, "position \"" + clip(position_text) + "\" is not one of I, TI, C, TE, E");
      continue;
    }
    if (!answer.contains("certificate")) {
      fail(number, "the answer has no \"certificate\"");
      continue;
    }
    try {
      const relpos::Certificate c = relpos::detail::io::certificate_from_tree(answer["certificate"]);
      if (auto reason = relpos::verify_certificate(*in.e, *in.p, *position, c))
        fail(number, position_text + ": " + clip(*reason));
      else if (auto margin_reason = margin_failure(*in.e, *in.p, answer))
        fail(number, "margin: " + clip(*margin_reason));
      else
        ++verified;
    } catch (const std::exception& err) {
      fail(number, position_text + ": " + clip(err.what()));
    }
  }
  if (input.bad() || answers.bad()) {
    std::cerr << "relpos verify: error reading the input files\n";
    return 2;
  }
  std::cout << "verified " << verified << ", failed " << failed << ", skipped " << skipped;
  if (unanswered) std::cout << ", unanswered " << unanswered;
  std::cout << "\n";
  if (finish_cout() != kExitOk) return kExitIo;
  return failed == 0 && unanswered == 0 ? 0 : 1;
}

}  // namespace relpos_cli
