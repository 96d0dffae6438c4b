#pragma once
// One writer per folder: an exclusive flock on DIR/.planter.lock, held while the object lives
// (the kernel lets it go when the program ends, however it ends). Every tool that writes a
// plan's folder, or runs live in one, takes it first; a second one is refused at once with
// one line, not left to race the first over the same runs (issue 53, item 5).
#include <string>

namespace planter::plan {

class FolderLock {
 public:
  // Creates DIR if needed. Throws std::runtime_error "DIR: `busy`" when another holds it.
  FolderLock(const std::string& dir, const std::string& busy);
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;
  ~FolderLock();

 private:
  int fd_ = -1;
};

}  // namespace planter::plan
