// Fuzz target: a sequence of frames from an untrusted bus into the simulated CANopen nodes (a
// CiA 402 drive and a CiA 404 load cell): SDO requests (PDO mapping and communication objects
// included), NMT, SYNC and RPDOs, in any order. Every frame the nodes send must fit a classic
// CAN frame, and nothing may read or write out of bounds (ASan) or hang.
//
// Input: records of 10 bytes: [selector][dlc][8 data]. The selector picks the COB-ID: the
// drive's or the load cell's SDO request, NMT, SYNC, or one of the drive's four RPDOs.
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "firmware/canopen/cob_id.h"
#include "hal/sim/virtual_can_bus.h"
#include "sim/devices/cia402_drive_device.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace planter;
  hal::sim::VirtualCanBus bus;
  auto& master = bus.add_endpoint();
  auto& drive_side = bus.add_endpoint();
  auto& cell_side = bus.add_endpoint();
  sim::Cia402DriveDevice drive({3, 0x20192, 0xAB, 0x402002, 1, 1, "roller actuator"}, drive_side);
  sim::Cia404ForceSensor cell({5, 0x20194, 0xCD, 0x404001, 1, 1, "load cell"}, cell_side);
  drive.power_on(0);
  cell.power_on(0);
  std::int64_t now_ns = 0;
  constexpr std::size_t kRecord = 10;
  for (std::size_t at = 0; at + kRecord <= size && at < 4000 * kRecord; at += kRecord) {
    const std::uint8_t selector = data[at];
    hal::CanFrame f{};
    switch (selector % 8) {
      case 0:
        f.id = canopen::kSdoRequestBase + 3;
        break;
      case 1:
        f.id = canopen::kSdoRequestBase + 5;
        break;
      case 2:
        f.id = canopen::kNmtCobId;
        break;
      case 3:
        f.id = canopen::kSyncCobId;
        break;
      default:
        f.id = canopen::kRpdoBase[selector % 8 - 4] + 3;
        break;
    }
    f.dlc = static_cast<std::uint8_t>(data[at + 1] % 9);
    std::memcpy(f.data.data(), data + at + 2, 8);
    master.send(f);
    now_ns += 1'000'000;
    drive.process(now_ns);
    cell.process(now_ns);
    hal::CanFrame out;
    while (master.receive(out)) {
      if (out.dlc > 8) __builtin_trap();
    }
  }
  return 0;
}
