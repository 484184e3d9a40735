#include "crossdiv/verification/suite/output_folder_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "crossdiv/error.h"
#include "crossdiv/io/output_file.h"

namespace crossdiv::verification {

OutputFolderLock::OutputFolderLock(const std::string& folder) {
    create_output_folder(folder);
    const std::string path = (std::filesystem::path(folder) / ".crossdiv-lock").string();
    fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0) throw InputError(path + ": cannot open the output folder's lock (" + std::strerror(errno) + ")");
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
        const int err = errno;
        ::close(fd_);
        fd_ = -1;
        if (err == EWOULDBLOCK)
            throw InputError(folder + ": another crossdiv suite or merge is writing its results there; wait for it, or "
                                      "give this one another --out");
        throw InputError(path + ": cannot lock the output folder (" + std::strerror(err) + ")");
    }
}

OutputFolderLock::~OutputFolderLock() {
    if (fd_ >= 0) ::close(fd_);  // closing the last descriptor releases the lock
}

}  // namespace crossdiv::verification
