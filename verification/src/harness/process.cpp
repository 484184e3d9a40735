#include "crossdiv/verification/harness/process.h"

#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "crossdiv/error.h"

extern char** environ;

namespace crossdiv::verification {

int run_process(const std::vector<std::string>& argv) {
    if (argv.empty()) throw InputError("run_process: no program given");
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    std::fflush(nullptr);  // our buffered lines first, then the program's
    pid_t pid = 0;
    if (const int err = posix_spawnp(&pid, args[0], nullptr, nullptr, args.data(), environ); err != 0)
        throw InputError("cannot start " + argv[0] + ": " + std::strerror(err));
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) throw InputError("waiting for " + argv[0] + ": " + std::strerror(errno));
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace crossdiv::verification
