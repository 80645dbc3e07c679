#pragma once
// CRC-32/ISO-HDLC (the zlib / PNG / Ethernet CRC): guards every replay record.
#include <cstdint>
#include <span>

namespace game {

// CRC of `bytes`; crc32("123456789") == 0xCBF43926.
uint32_t crc32(std::span<const uint8_t> bytes);

}  // namespace game
