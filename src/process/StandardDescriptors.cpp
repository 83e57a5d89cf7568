#include "process/StandardDescriptors.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>

namespace termshade {

void GuardClosedStandardDescriptors() {
  for (int fd = STDIN_FILENO; fd <= STDERR_FILENO; ++fd) {
    if (fcntl(fd, F_GETFD) >= 0 || errno != EBADF) continue;
    // The lowest free descriptor: this one (those below are open by now).
    const int guard = open("/dev/null", O_RDONLY | O_NOCTTY);
    if (guard >= 0 && guard != fd) close(guard);
  }
}

}  // namespace termshade
