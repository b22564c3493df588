// common/core/child_process.cpp — fork + exec with pipes, poll with a deadline
// (POSIX); CreateProcess with pipes, a thread feeding the input and a polled
// read with a deadline (Windows, which has neither fork nor poll on pipes).
#include "common/core/child_process.hpp"

#include <chrono>
#include <climits>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>

#ifdef _WIN32
#ifndef NOMINMAX
#define NOMINMAX
#endif
#include <windows.h>

#include <thread>

namespace ts {
namespace {
std::wstring widen(const std::string& s) {
  if (s.empty()) return std::wstring();
  const int n = MultiByteToWideChar(CP_UTF8, 0, s.data(), int(s.size()), nullptr, 0);
  std::wstring w(size_t(n), L'\0');
  MultiByteToWideChar(CP_UTF8, 0, s.data(), int(s.size()), w.data(), n);
  return w;
}
std::string narrow(const std::wstring& w) {
  if (w.empty()) return std::string();
  const int n = WideCharToMultiByte(CP_UTF8, 0, w.data(), int(w.size()), nullptr, 0, nullptr, nullptr);
  std::string s(size_t(n), '\0');
  WideCharToMultiByte(CP_UTF8, 0, w.data(), int(w.size()), s.data(), n, nullptr, nullptr);
  return s;
}
// One argument as the C runtime's command-line parser reads it back:
// quoted when it holds a space, tab or quote; a quote escaped with a
// backslash, and the backslashes before a quote (or the closing quote)
// doubled.
std::wstring quoteArg(const std::wstring& a) {
  if (!a.empty() && a.find_first_of(L" \t\"") == std::wstring::npos) return a;
  std::wstring q = L"\"";
  size_t slashes = 0;
  for (wchar_t c : a) {
    if (c == L'\\') {
      ++slashes;
      continue;
    }
    if (c == L'"') q.append(slashes * 2 + 1, L'\\');
    else q.append(slashes, L'\\');
    slashes = 0;
    q += c;
  }
  q.append(slashes * 2, L'\\');
  return q + L"\"";
}
std::string lastError(const char* what) {
  return std::string(what) + ": Windows error " + std::to_string(GetLastError());
}
}  // namespace

ProcessResult runProcess(const std::vector<std::string>& argv, const std::string& input, double timeoutSeconds) {
  ProcessResult r;
  if (argv.empty()) return r.out = "no program to run", r;
  SECURITY_ATTRIBUTES sa{sizeof(SECURITY_ATTRIBUTES), nullptr, TRUE};
  HANDLE inRead = nullptr, inWrite = nullptr, outRead = nullptr, outWrite = nullptr;
  if (!CreatePipe(&inRead, &inWrite, &sa, 0)) return r.out = lastError("CreatePipe"), r;
  if (!CreatePipe(&outRead, &outWrite, &sa, 0)) {
    CloseHandle(inRead), CloseHandle(inWrite);
    return r.out = lastError("CreatePipe"), r;
  }
  // The child inherits only its ends.
  SetHandleInformation(inWrite, HANDLE_FLAG_INHERIT, 0);
  SetHandleInformation(outRead, HANDLE_FLAG_INHERIT, 0);
  std::wstring cmd;
  for (const auto& a : argv) cmd += (cmd.empty() ? L"" : L" ") + quoteArg(widen(a));
  STARTUPINFOW si{};
  si.cb = sizeof si;
  si.dwFlags = STARTF_USESTDHANDLES;
  si.hStdInput = inRead;
  si.hStdOutput = outWrite;
  si.hStdError = outWrite;
  PROCESS_INFORMATION pi{};
  const std::wstring exe = widen(argv[0]);
  const BOOL ok = CreateProcessW(exe.c_str(), cmd.data(), nullptr, nullptr, TRUE, CREATE_NO_WINDOW, nullptr, nullptr,
                                 &si, &pi);
  CloseHandle(inRead), CloseHandle(outWrite);
  if (!ok) {
    CloseHandle(inWrite), CloseHandle(outRead);
    r.out = "cannot run the program\n";
    return r;
  }
  CloseHandle(pi.hThread);
  r.started = true;
  // A thread feeds the input (a pipe's write blocks while the child does not
  // read); it ends when all is written or the child's end is gone.
  std::thread feeder([inWrite, &input] {
    size_t sent = 0;
    while (sent < input.size()) {
      DWORD n = 0;
      const DWORD want = DWORD(std::min<size_t>(input.size() - sent, 65536));
      if (!WriteFile(inWrite, input.data() + sent, want, &n, nullptr)) break;
      sent += n;
    }
    CloseHandle(inWrite);
  });
  const auto start = std::chrono::steady_clock::now();
  char buf[4096];
  for (;;) {
    DWORD avail = 0;
    if (!PeekNamedPipe(outRead, nullptr, 0, nullptr, &avail, nullptr)) break;  // closed: it ended
    if (avail > 0) {
      DWORD n = 0;
      if (!ReadFile(outRead, buf, std::min<DWORD>(avail, sizeof buf), &n, nullptr) || n == 0) break;
      r.out.append(buf, n);
      continue;
    }
    if (WaitForSingleObject(pi.hProcess, 0) == WAIT_OBJECT_0) {
      // Ended: what it wrote last is in the pipe already.
      while (PeekNamedPipe(outRead, nullptr, 0, nullptr, &avail, nullptr) && avail > 0) {
        DWORD n = 0;
        if (!ReadFile(outRead, buf, std::min<DWORD>(avail, sizeof buf), &n, nullptr) || n == 0) break;
        r.out.append(buf, n);
      }
      break;
    }
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() >= timeoutSeconds) {
      r.timedOut = true;
      TerminateProcess(pi.hProcess, 1);
      break;
    }
    Sleep(5);
  }
  WaitForSingleObject(pi.hProcess, INFINITE);
  CloseHandle(outRead);  // a feeder still blocked on a full pipe fails now
  feeder.join();
  DWORD code = 0;
  GetExitCodeProcess(pi.hProcess, &code);
  CloseHandle(pi.hProcess);
  r.exitCode = r.timedOut ? -1 : int(code);
  return r;
}

std::string programFolder() {
  std::wstring buf(32768, L'\0');
  const DWORD n = GetModuleFileNameW(nullptr, buf.data(), DWORD(buf.size()));
  if (n == 0) return ".";
  std::string p = narrow(buf.substr(0, n));
  const size_t slash = p.find_last_of("\\/");
  return slash == std::string::npos ? "." : p.substr(0, slash);
}
}  // namespace ts

#else  // POSIX

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>
#ifdef __APPLE__
#include <mach-o/dyld.h>
#include <pthread.h>
#include <pthread/qos.h>

#include <cstdlib>
#endif

namespace ts {
namespace {
// A pipe whose ends close on exec.  macOS has no pipe2: there the flag is set
// right after (nothing else forks while the suite starts a child).
int pipeCloseOnExec(int fds[2]) {
#ifdef __APPLE__
  if (pipe(fds) != 0) return -1;
  fcntl(fds[0], F_SETFD, FD_CLOEXEC);
  fcntl(fds[1], F_SETFD, FD_CLOEXEC);
  return 0;
#else
  return pipe2(fds, O_CLOEXEC);
#endif
}
}  // namespace

ProcessResult runProcess(const std::vector<std::string>& argv, const std::string& input, double timeoutSeconds) {
  ProcessResult r;
  if (argv.empty()) return r.out = "no program to run", r;
  int in[2], out[2];
  if (pipeCloseOnExec(in) != 0) return r.out = std::string("pipe: ") + std::strerror(errno), r;
  if (pipeCloseOnExec(out) != 0) {
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
    const double left = timeoutSeconds -
                        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
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
#ifdef __APPLE__
  // macOS has no /proc: dyld knows the path the program was started by.
  char raw[4096], buf[PATH_MAX];
  uint32_t size = sizeof raw;
  if (_NSGetExecutablePath(raw, &size) != 0 || !realpath(raw, buf)) return ".";
  std::string p(buf);
#else
  char buf[4096];
  const ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
  if (n <= 0) return ".";
  std::string p(buf, size_t(n));
#endif
  const size_t slash = p.rfind('/');
  return slash == std::string::npos ? "." : p.substr(0, slash);
}
}  // namespace ts
#endif  // POSIX

namespace ts {
void useUtf8Console() {
#ifdef _WIN32
  SetConsoleOutputCP(CP_UTF8);
#endif
}

void lowerThreadPriority() {
#ifdef _WIN32
  SetThreadPriority(GetCurrentThread(), THREAD_PRIORITY_BELOW_NORMAL);
#elif defined(__APPLE__)
  // macOS has no per-thread nice value (PRIO_PROCESS would lower the whole
  // program): the thread's quality-of-service class is its priority.
  pthread_set_qos_class_self_np(QOS_CLASS_UTILITY, 0);
#else
  setpriority(PRIO_PROCESS, id_t(::syscall(SYS_gettid)), 5);
#endif
}

std::string programPath(const std::string& name) {
#ifdef _WIN32
  return programFolder() + "/" + name + ".exe";
#else
  return programFolder() + "/" + name;
#endif
}

std::string makeTempFolder(const std::string& prefix) {
  // A random name created with create_directory, which fails when the name
  // exists: the same guarantee as mkdtemp, on every system.
  std::random_device rd;
  std::mt19937_64 gen((uint64_t(rd()) << 32) ^ rd());
  std::error_code ec;
  const std::filesystem::path base = std::filesystem::temp_directory_path(ec);
  if (ec) return "";
  for (int attempt = 0; attempt < 16; ++attempt) {
    char suffix[17];
    std::snprintf(suffix, sizeof suffix, "%016llx", static_cast<unsigned long long>(gen()));
    const std::filesystem::path p = base / (prefix + suffix);
    if (std::filesystem::create_directory(p, ec)) return p.string();
  }
  return "";
}
}  // namespace ts
