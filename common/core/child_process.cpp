// common/core/child_process.cpp — fork + exec with pipes, poll with a deadline.
#include "common/core/child_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <climits>
#include <cstring>

namespace ts {
ProcessResult runProcess(const std::vector<std::string>& argv, const std::string& input, double timeoutSeconds) {
  ProcessResult r;
  if (argv.empty()) return r.out = "no program to run", r;
  int in[2], out[2];
  if (pipe2(in, O_CLOEXEC) != 0) return r.out = std::string("pipe: ") + std::strerror(errno), r;
  if (pipe2(out, O_CLOEXEC) != 0) {
    close(in[0]), close(in[1]);
    return r.out = std::string("pipe: ") + std::strerror(errno), r;
  }
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const pid_t pid = fork();
  if (pid < 0) {
    for (int fd : {in[0], in[1], out[0], out[1]}) close(fd);
    return r.out = std::string("fork: ") + std::strerror(errno), r;
  }
  if (pid == 0) {  // the child: stdin from `in`, stdout and stderr to `out`
    dup2(in[0], STDIN_FILENO), dup2(out[1], STDOUT_FILENO), dup2(out[1], STDERR_FILENO);
    execv(args[0], args.data());
    const char* why = "cannot run the program\n";
    (void)!write(STDERR_FILENO, why, std::strlen(why));
    _exit(127);
  }
  close(in[0]), close(out[1]);
  r.started = true;
  // Feed the input and read the output together (either may fill its pipe).
  size_t sent = 0;
  if (input.empty()) close(in[1]), in[1] = -1;
  else fcntl(in[1], F_SETFL, O_NONBLOCK);
  const auto start = std::chrono::steady_clock::now();
  while (true) {
    const double left = timeoutSeconds - std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (left <= 0) {
      r.timedOut = true;
      break;
    }
    pollfd p[2] = {{out[0], POLLIN, 0}, {in[1], POLLOUT, 0}};
    if (poll(p, in[1] >= 0 ? 2 : 1, int(std::min(left, 1.0) * 1000) + 1) <= 0) continue;
    if (in[1] >= 0 && (p[1].revents & (POLLOUT | POLLERR | POLLHUP))) {
      const ssize_t n = write(in[1], input.data() + sent, std::min<size_t>(input.size() - sent, PIPE_BUF));
      if (n > 0) sent += size_t(n);
      if (n < 0 && errno != EAGAIN) sent = input.size();  // the child stopped reading
      if (sent == input.size()) close(in[1]), in[1] = -1;
    }
    if (p[0].revents & (POLLIN | POLLHUP | POLLERR)) {
      char buf[4096];
      const ssize_t n = read(out[0], buf, sizeof buf);
      if (n <= 0) break;  // it closed its output: it ended
      r.out.append(buf, size_t(n));
    }
  }
  if (in[1] >= 0) close(in[1]);
  close(out[0]);
  if (r.timedOut) kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

std::string programFolder() {
  char buf[4096];
  const ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
  if (n <= 0) return ".";
  std::string p(buf, size_t(n));
  const size_t slash = p.rfind('/');
  return slash == std::string::npos ? "." : p.substr(0, slash);
}
}  // namespace ts
