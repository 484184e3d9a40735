// Programs kept running between runs (program_server.h): each run keeps its own verdict
// whatever the one before did to the server, and a served program fails in the same named ways
// as one started per run.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "crossdiv/datasets/bundled.h"
#include "crossdiv/error.h"
#include "crossdiv/verification/comparisons/refinement_comparison.h"
#include "crossdiv/verification/harness/program_server.h"
#include "crossdiv/verification/implementations/program_implementation.h"
#include "test_inputs.h"

namespace crossdiv::verification {
namespace {

using test::kSource;

const std::string kServingProgram = kSource + "/verification/tests/subjects/serving_program.py";
const std::string kMisbehaving = kSource + "/verification/tests/subjects/misbehaving_subject.py";

/// A time limit no healthy run of the test programs comes near (a Python start is 0.1 s).
constexpr double kRunLimit = 30;

bool is_zombie(pid_t pid) {
    std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
    std::string text;
    if (!std::getline(stat, text)) return false;
    const size_t close = text.rfind(')');
    return close != std::string::npos && close + 2 < text.size() && text[close + 2] == 'Z';
}

/// The process id a `pid` request says on stderr.
pid_t served_pid(ProgramServer& server) {
    const ServedRun r = server.run({"pid"}, kRunLimit);
    EXPECT_EQ(r.process.exit_code, 0) << r.stderr_text;
    return static_cast<pid_t>(std::stol(r.stderr_text));
}

TEST(ProgramServer, StartsOnceAndAnswersEveryRunWithItsStatusAndItsOwnStderr) {
    ProgramServer server({"python3", kServingProgram, "--serve"}, "serving-test");
    const ServedRun first = server.run({"ok"}, kRunLimit);
    EXPECT_TRUE(first.process.started);
    EXPECT_TRUE(first.started_now);
    EXPECT_EQ(first.process.exit_code, 0);
    EXPECT_EQ(first.stderr_text, "");
    const ServedRun refused = server.run({"status", "4"}, kRunLimit);
    EXPECT_FALSE(refused.started_now);
    EXPECT_EQ(refused.process.exit_code, 4);
    EXPECT_EQ(refused.stderr_text, "refused this one");
    // The next run's stderr is its own: nothing of the refusal's.
    const ServedRun after = server.run({"ok"}, kRunLimit);
    EXPECT_EQ(after.process.exit_code, 0);
    EXPECT_EQ(after.stderr_text, "");
    EXPECT_EQ(server.starts(), 1);
}

TEST(ProgramServer, ARunThatCrashesItIsThatRunsCrashAndTheNextRunStartsItAgain) {
    ProgramServer server({"python3", kServingProgram, "--serve"}, "serving-test");
    ASSERT_EQ(server.run({"ok"}, kRunLimit).process.exit_code, 0);
    const ServedRun crash = server.run({"crash"}, kRunLimit);
    EXPECT_EQ(crash.process.signal, SIGSEGV);
    EXPECT_FALSE(crash.out_of_turn);
    const ServedRun next = server.run({"ok"}, kRunLimit);
    EXPECT_TRUE(next.started_now);
    EXPECT_EQ(next.process.exit_code, 0);
    EXPECT_EQ(next.process.signal, 0);
    EXPECT_EQ(server.starts(), 2);
}

TEST(ProgramServer, ARunPastItsLimitIsATimeOutAndItsServerIsKilledWithItsGroup) {
    ProgramServer server({"python3", kServingProgram, "--serve"}, "serving-test");
    const pid_t first = served_pid(server);
    const ServedRun hang = server.run({"hang"}, 1.0);
    EXPECT_TRUE(hang.process.timed_out);
    EXPECT_GE(hang.process.seconds, 1.0);
    EXPECT_LT(hang.process.seconds, kRunLimit);
    EXPECT_NE(::kill(first, 0), 0) << "the hung server " << first << " is still running";
    const pid_t second = served_pid(server);
    EXPECT_NE(second, first);
    EXPECT_EQ(server.starts(), 2);
}

TEST(ProgramServer, AnAnswerOutOfTurnOrAnEndWithoutOneBreaksTheProtocol) {
    ProgramServer server({"python3", kServingProgram, "--serve"}, "serving-test");
    const ServedRun lie = server.run({"lie"}, kRunLimit);
    EXPECT_TRUE(lie.out_of_turn);
    EXPECT_NE(lie.stderr_text.find("answered '999999 0' to request 1"), std::string::npos) << lie.stderr_text;
    const ServedRun quiet = server.run({"quiet-exit"}, kRunLimit);
    EXPECT_TRUE(quiet.out_of_turn);
    EXPECT_NE(quiet.stderr_text.find("closed its answers"), std::string::npos) << quiet.stderr_text;
    EXPECT_EQ(server.run({"ok"}, kRunLimit).process.exit_code, 0);
    EXPECT_EQ(server.starts(), 3);
}

TEST(ProgramServer, AServerKilledBetweenRunsIsStartedAgainForTheNextRun) {
    ProgramServer server({"python3", kServingProgram, "--serve"}, "serving-test");
    const pid_t first = served_pid(server);
    ASSERT_EQ(::kill(first, SIGKILL), 0);
    // Dead before the next run asks (a zombie until that run reaps it).
    for (int i = 0; i < 500 && !is_zombie(first); ++i) usleep(2000);
    ASSERT_TRUE(is_zombie(first));
    const ServedRun next = server.run({"ok"}, kRunLimit);
    EXPECT_EQ(next.process.exit_code, 0) << next.stderr_text;
    EXPECT_EQ(next.process.signal, 0);
    EXPECT_FALSE(next.out_of_turn);
}

TEST(ProgramServer, ThatCannotStartSaysWhy) {
    ProgramServer server({"/nonexistent/server", "--serve"}, "serving-test");
    const ServedRun r = server.run({"ok"}, kRunLimit);
    EXPECT_FALSE(r.process.started);
    EXPECT_NE(r.process.start_error.find("cannot start /nonexistent/server"), std::string::npos) << r.process.start_error;
}

TEST(ProgramServer, AForkedProcessRunsAServerOfItsOwnAndLeavesItsParentsAlone) {
    ProgramServer server({"python3", kServingProgram, "--serve"}, "serving-test");
    const pid_t parents = served_pid(server);
    int pipe_fds[2];
    ASSERT_EQ(pipe(pipe_fds), 0);
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        close(pipe_fds[0]);
        const ServedRun r = server.run({"pid"}, kRunLimit);
        const long pid = r.process.exit_code == 0 ? std::stol(r.stderr_text) : -1;
        (void)!write(pipe_fds[1], &pid, sizeof pid);
        stop_program_servers();
        _exit(0);
    }
    close(pipe_fds[1]);
    long childs = 0;
    ASSERT_EQ(read(pipe_fds[0], &childs, sizeof childs), static_cast<ssize_t>(sizeof childs));
    close(pipe_fds[0]);
    int status = 0;
    waitpid(child, &status, 0);
    EXPECT_GT(childs, 0);
    EXPECT_NE(childs, parents);
    // The parent's server still answers, the same process.
    EXPECT_EQ(served_pid(server), parents);
    EXPECT_EQ(server.starts(), 1);
}

TEST(ProgramServer, StoppedWithTheOthersOfItsProcessLeavesNoFolderAndStartsAgainOnItsNextRun) {
    ProgramServer server({"python3", kServingProgram, "--serve"}, "serving-test");
    const ServedRun where = server.run({"cwd"}, kRunLimit);
    ASSERT_EQ(where.process.exit_code, 0) << where.stderr_text;
    const std::filesystem::path folder = where.stderr_text;
    EXPECT_NE(folder.filename().string().find("crossdiv-serving-test-server-"), std::string::npos) << folder;
    const pid_t first = served_pid(server);
    ASSERT_TRUE(std::filesystem::is_directory(folder));
    ASSERT_TRUE(server.running());

    stop_program_servers();
    EXPECT_FALSE(server.running());
    EXPECT_FALSE(std::filesystem::exists(folder)) << folder;
    EXPECT_EQ(kill(first, 0), -1) << "the server process is still there";

    EXPECT_NE(served_pid(server), first);
    EXPECT_EQ(server.starts(), 2);
}

ProgramSpec served_subject(double timeout) {
    ProgramSpec spec;
    spec.name = "served";
    spec.command = "python3 " + kMisbehaving + " MODE {in} {levels} {out}";
    spec.serve = "python3 " + kMisbehaving + " --serve";
    spec.schemes = {Scheme::Loop};
    spec.timeout_seconds = timeout;
    return spec;
}

struct ServedFailure {
    const char* mode;
    RunStatus status;
    const char* in_message;
};

class ServedProgramFailure : public ::testing::TestWithParam<ServedFailure> {};

TEST_P(ServedProgramFailure, IsNamedAsWhenTheProgramStartsForEachRun) {
    const ServedFailure f = GetParam();
    ProgramSpec spec = served_subject(3);
    spec.command.replace(spec.command.find("MODE"), 4, f.mode);
    const auto subject = make_program_implementation(spec);
    RefinementRequest req;
    req.levels = 2;
    req.subject = subject.get();
    const RefinementComparison c = compare_refinement(datasets::bundled_mesh("icosahedron"), "icosahedron", req);
    EXPECT_EQ(c.subject_outcome.status, f.status) << c.subject_outcome.summary();
    EXPECT_NE(c.subject_outcome.message.find(f.in_message), std::string::npos) << c.subject_outcome.message;
}

INSTANTIATE_TEST_SUITE_P(
    Modes, ServedProgramFailure,
    ::testing::Values(ServedFailure{"crash", RunStatus::Crashed, "signal 11"},
                      ServedFailure{"hang", RunStatus::Timeout, "no result after 3 s"},
                      ServedFailure{"exit", RunStatus::ExitStatus, "half-edge table overflow"},
                      ServedFailure{"nothing", RunStatus::NoOutput, "no output file out.obj"},
                      ServedFailure{"wrong-count", RunStatus::WrongCount, "42 vertices, 80 faces"}),
    [](const auto& info) {
        std::string n = info.param.mode;
        for (char& ch : n)
            if (ch == '-') ch = '_';
        return n;
    });

TEST(ServedProgram, GivesTheResultOfTheProgramStartedPerRunBitForBit) {
    ProgramSpec per_run = served_subject(kRunLimit);
    per_run.command.replace(per_run.command.find("MODE"), 4, "shuffle");
    per_run.serve.clear();
    ProgramSpec served = served_subject(kRunLimit);
    served.command.replace(served.command.find("MODE"), 4, "shuffle");
    const auto a = make_program_implementation(per_run);
    const auto b = make_program_implementation(served);
    const PolyMesh mesh = datasets::bundled_mesh("open-patch");  // interior, boundary and corner vertices
    for (int levels = 1; levels <= 2; ++levels) {
        const RefineRequest request{Scheme::Loop, {}, levels};
        const PolyMesh x = a->refine_last(mesh, request), y = b->refine_last(mesh, request);
        // "shuffle" draws its order from a fixed seed: the same numbering from either.
        EXPECT_EQ(x.face_vertices, y.face_vertices);
        ASSERT_EQ(x.positions.size(), y.positions.size());
        for (size_t i = 0; i < x.positions.size(); ++i) EXPECT_EQ(x.positions[i], y.positions[i]);
    }
}

TEST(ServedProgram, IsOneProcessForEveryRunOfThisProcess) {
    // `pid` says the server's process id and writes no mesh: each run is a NoOutput failure
    // whose stderr names the process that ran it.
    ProgramSpec spec;
    spec.name = "served";
    spec.command = "python3 " + kServingProgram + " pid {in} {out}";
    spec.serve = "python3 " + kServingProgram + " --serve";
    spec.schemes = {Scheme::Loop};
    const auto subject = make_program_implementation(spec);
    std::vector<std::string> said;
    for (int run = 0; run < 3; ++run) {
        try {
            subject->refine_last(datasets::bundled_mesh("tetrahedron"), {Scheme::Loop, {}, 1});
            ADD_FAILURE() << "a run without an output file passed";
        } catch (const ImplementationFailure& e) {
            EXPECT_EQ(e.status(), RunStatus::NoOutput);
            const std::string what = e.what();
            const size_t at = what.find("stderr: ");
            ASSERT_NE(at, std::string::npos) << what;
            said.push_back(what.substr(at + 8));
        }
    }
    ASSERT_EQ(said.size(), 3u);
    EXPECT_EQ(said[0], said[1]);
    EXPECT_EQ(said[1], said[2]);
}

TEST(ServedProgram, ItsServeCommandStartsTheSameProgramAndNamesNoValueOfARun) {
    ProgramSpec spec = served_subject(kRunLimit);
    spec.serve = "python3 " + kMisbehaving + " --serve {levels}";
    EXPECT_THROW(check_program_spec(spec), InputError);
    spec.serve = "python2 " + kMisbehaving + " --serve";
    EXPECT_THROW(check_program_spec(spec), InputError);
    spec.serve = "python3 {adapters}/x.py --serve";  // the same interpreter, another script: allowed, one word shared
    EXPECT_NO_THROW(check_program_spec(spec));
}

}  // namespace
}  // namespace crossdiv::verification
