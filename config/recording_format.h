#pragma once
// The controller's part of a recording row (docs/recording-format.md), shared by planterd and the
// simulator so that a field log and a simulated one have the same columns and precision. Both
// the header and the row come from the signal table (firmware/io/signal_table.h).
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "firmware/controller/telemetry.h"

namespace planter::config {

// The metadata line that declares the board's SYNC period. CiA 301 (synchronous PDOs): a drive
// acts on the data of a synchronous RPDO at the next SYNC, so a command recorded in one row acts
// one SYNC period later. planter-fit takes that path as part of the drives' nominal structures.
inline constexpr std::string_view kSyncPeriodKey = "sync_period_s";
inline constexpr double kSyncPeriodMaxS = 1.0;  // the board file's largest sync_period_ms
// The value of that line in seconds ("0.01").
std::string sync_period_value(std::int64_t sync_period_ns);

// Header of the controller columns, without a trailing newline.
std::string controller_columns();

// Writes the controller columns of one row (no newline) into out; returns the length, or a
// value >= size when it did not fit. No allocation.
int format_controller_columns(char* out, std::size_t size, double t_s, const Telemetry& c);

// A row of text built into a fixed buffer without printf: numbers as "%.*f" would write them,
// byte for byte (std::to_chars, exact like glibc's printf; printf's multi-precision path was
// about a third of the simulator's time, issue 30). length() counts what was asked for, so a
// length >= the buffer's size says the row was cut.
class RowText {
 public:
  // `written`: characters already in out (a row continued).
  RowText(char* out, std::size_t size, std::size_t written = 0)
      : out_(out), size_(size), total_(written) {}
  void text(std::string_view s);
  void fixed(double v, int decimals);
  void integer(long long v);
  void separator() { text(","); }
  [[nodiscard]] std::size_t length() const { return total_; }

 private:
  char* out_;
  std::size_t size_;
  std::size_t total_;
};

}  // namespace planter::config
