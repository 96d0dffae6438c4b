#pragma once
// The version every program prints with --version (and help2man reads for the man pages):
// the project's version plus git's commit count and hash at configure time (cmake/version.cmake).
namespace planter::apps {

const char* version();

}  // namespace planter::apps
