// The commands of the relpos CLI (doc/cli.md), each given the arguments after its name. They
// throw UsageError (options.hpp) for a bad command line and return the exit code (common.hpp).
#pragma once

#include <ostream>

#include "options.hpp"

namespace relpos_cli {

int run_classify(Args& args);  // cli/main.cpp
int run_batch(Args& args);     // cli/main.cpp
int run_scene(Args& args);     // cli/scene.cpp
int run_motion(Args& args);    // cli/motion.cpp
int run_verify(Args& args);    // cli/verify.cpp
int run_cases(Args& args);     // cli/cases.cpp
int run_judge(Args& args);     // cli/judge.cpp
void print_classify_help(std::ostream& os);
void print_batch_help(std::ostream& os);
void print_scene_help(std::ostream& os);
void print_motion_help(std::ostream& os);
void print_verify_help(std::ostream& os);
void print_cases_help(std::ostream& os);
void print_judge_help(std::ostream& os);

}  // namespace relpos_cli
