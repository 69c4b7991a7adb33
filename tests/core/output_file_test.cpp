#include "core/output_file.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <set>

#include "core/text_file.h"

namespace canopy {
namespace {

namespace fs = std::filesystem;

class OutputFile : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("canopy_output_file_" +
            std::string(testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
            std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::set<std::string> names() const {
    std::set<std::string> found;
    for (const auto& entry : fs::directory_iterator(dir_))
      found.insert(entry.path().filename().string());
    return found;
  }
  fs::path dir_;
};

TEST_F(OutputFile, AppearsOnlyWhenCommitted) {
  {
    AtomicFile file(dir_ / "a.txt");
    file.write("one ");
    file.write(std::string(100000, 'x'));  // larger than the buffer
    EXPECT_EQ(names().count("a.txt"), 0u);
    file.commit();
  }
  EXPECT_EQ(names(), std::set<std::string>{"a.txt"});
  EXPECT_EQ(readTextFile(dir_ / "a.txt")->size(), 4u + 100000u);
}

TEST_F(OutputFile, LeavesNothingWithoutCommit) {
  writeFileAtomically(dir_ / "a.txt", "old");
  {
    AtomicFile file(dir_ / "a.txt");
    file.write("new, never finished");
  }
  EXPECT_EQ(names(), std::set<std::string>{"a.txt"});
  EXPECT_EQ(readTextFile(dir_ / "a.txt"), "old");
}

TEST_F(OutputFile, ReplacesALinkInsteadOfFollowingIt) {
  std::ofstream(dir_ / "target") << "precious";
  fs::create_symlink(dir_ / "target", dir_ / "a.txt");
  fs::create_symlink(dir_ / "target", dir_ / "a.txt.tmp");  // the old fixed temporary name
  writeFileAtomically(dir_ / "a.txt", "mine");
  EXPECT_EQ(readTextFile(dir_ / "target"), "precious");
  EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(dir_ / "a.txt")));
  EXPECT_EQ(readTextFile(dir_ / "a.txt"), "mine");
}

TEST_F(OutputFile, ADirectoryInTheWayIsAWriteErrorNamingTheFile) {
  fs::create_directories(dir_ / "a.txt" / "inside");
  try {
    writeFileAtomically(dir_ / "a.txt", "text");
    FAIL() << "no WriteError";
  } catch (const WriteError& e) {
    EXPECT_EQ(e.path(), dir_ / "a.txt");
    EXPECT_NE(std::string(e.what()).find("cannot write '" + (dir_ / "a.txt").string() + "'"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(names(), std::set<std::string>{"a.txt"});  // no temporary left
}

// Issue 47: a node that is not a regular file is never replaced, whether it is there when the
// file is begun (a FIFO) or put there while it is written (a device node, made where mknod is
// permitted, else a FIFO): OutputRefused, the node untouched, no temporary left.
TEST_F(OutputFile, ANodeThatIsNotARegularFileIsRefusedAndLeftAsItWas) {
  const fs::path fifo = dir_ / "fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_THROW(writeFileAtomically(fifo, "text"), OutputRefused);
  EXPECT_THROW(removeOutputFile(fifo), OutputRefused);
  EXPECT_TRUE(fs::is_fifo(fs::symlink_status(fifo)));

  const fs::path late = dir_ / "late";
  {
    AtomicFile file(late);
    file.write("text");
    const bool device = ::mknod(late.c_str(), S_IFCHR | 0600, makedev(1, 3)) == 0;
    if (!device) {
      ASSERT_EQ(::mkfifo(late.c_str(), 0600), 0);
    }
    try {
      file.commit();
      FAIL() << "no OutputRefused";
    } catch (const OutputRefused& e) {
      EXPECT_NE(std::string(e.what()).find(device ? "a character device" : "a FIFO"),
                std::string::npos)
          << e.what();
    }
    struct stat info {};
    ASSERT_EQ(::lstat(late.c_str(), &info), 0);
    EXPECT_EQ(info.st_mode & S_IFMT, static_cast<unsigned>(device ? S_IFCHR : S_IFIFO));
    if (device) {
      EXPECT_EQ(info.st_rdev, makedev(1, 3));
    }
  }
  EXPECT_EQ(names(), (std::set<std::string>{"fifo", "late"}));  // no temporary left
  checkOutputFile(dir_ / "absent");                             // absent: nothing to refuse
  std::ofstream(dir_ / "regular") << "x";
  checkOutputFile(dir_ / "regular");
  EXPECT_THROW(checkOutputEntries(dir_), OutputRefused);

  // A socket (bound in a fresh folder: checkOutputEntries sees only it besides files).
  const fs::path sockets = dir_ / "sockets";
  fs::create_directories(sockets);
  const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
  ASSERT_GE(fd, 0);
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  const std::string socket_path = (sockets / "s").string();
  ASSERT_LT(socket_path.size(), sizeof address.sun_path);
  std::copy(socket_path.begin(), socket_path.end(), address.sun_path);
  ASSERT_EQ(::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
  try {
    writeFileAtomically(sockets / "s", "text");
    ADD_FAILURE() << "no OutputRefused";
  } catch (const OutputRefused& e) {
    EXPECT_NE(std::string(e.what()).find("exists and is a socket"), std::string::npos) << e.what();
  }
  EXPECT_THROW(checkOutputEntries(sockets), OutputRefused);
  ::close(fd);
  EXPECT_TRUE(fs::is_socket(fs::symlink_status(sockets / "s")));
}

// Files limited to 1000 bytes (RLIMIT_FSIZE, SIGXFSZ ignored): the write of 5000 fails with EFBIG,
// as on a full disk. In a child process, so that the limit stays there.
TEST_F(OutputFile, AFailedWriteThrowsAndRemovesTheTemporary) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{1000, 1000};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    try {
      writeFileAtomically(dir_ / "big.txt", std::string(5000, 'x'));
    } catch (const WriteError& e) {
      const std::string what = e.what();
      ::_exit(what.find("big.txt': File too large") != std::string::npos ? 0 : 2);
    }
    ::_exit(1);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "1: no error, 2: wrong message";
  EXPECT_EQ(names(), std::set<std::string>{});
}

TEST_F(OutputFile, DirectoriesBelowTheRootAreNeverLinks) {
  fs::create_directories(dir_ / "elsewhere");
  fs::create_directory_symlink(dir_ / "elsewhere", dir_ / "root");  // the user's own link: fine
  makeOutputDirectories(dir_ / "root" / "a" / "b", dir_ / "root");
  EXPECT_TRUE(fs::is_directory(dir_ / "elsewhere" / "a" / "b"));

  fs::create_directory_symlink(dir_ / "elsewhere", dir_ / "root" / "a" / "planted");
  EXPECT_THROW(makeOutputDirectories(dir_ / "root" / "a" / "planted" / "c", dir_ / "root"),
               WriteError);
  EXPECT_THROW(checkOutputDirectories(dir_ / "root" / "a" / "planted", dir_ / "root"), WriteError);
  EXPECT_FALSE(fs::exists(dir_ / "elsewhere" / "c"));
  std::ofstream(dir_ / "root" / "file") << "x";
  EXPECT_THROW(makeOutputDirectories(dir_ / "root" / "file" / "d", dir_ / "root"), WriteError);
  EXPECT_THROW(makeOutputDirectories(dir_ / "outside", dir_ / "root"), WriteError);
  checkOutputDirectories(dir_ / "root" / "new" / "deeper", dir_ / "root");  // absent is fine
  EXPECT_FALSE(fs::exists(dir_ / "root" / "new"));
}

TEST(SafeFileName, IsOneComponentThatCannotLeaveItsDirectory) {
  EXPECT_EQ(safeFileName("occlusion_sharing"), "occlusion_sharing");
  EXPECT_EQ(safeFileName("demo-2.v1"), "demo-2.v1");
  EXPECT_EQ(safeFileName("../../x"), "_._.._x");
  EXPECT_EQ(safeFileName(".."), "_.");
  EXPECT_EQ(safeFileName("."), "_");
  EXPECT_EQ(safeFileName(""), "_");
  EXPECT_EQ(safeFileName("a/b"), "a_b");
  EXPECT_EQ(safeFileName("/etc"), "_etc");
  EXPECT_EQ(safeFileName("\x1b[2J"), "__2J");
  EXPECT_EQ(safeFileName("Ålesund"), "__lesund");  // two bytes of UTF-8, two '_'
  EXPECT_EQ(safeFileName(std::string(300, 'a')), std::string(kMaxSafeFileName, 'a'));
}

}  // namespace
}  // namespace canopy
