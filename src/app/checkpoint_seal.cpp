#include "slipwave/app/checkpoint_seal.hpp"

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

namespace slipwave::app {
namespace {

constexpr uint64_t kSealMagic = 0x4c41455350435753ull; // "SWCPSEAL"
struct Seal {
  uint64_t magic, length, checksum;
};

// FNV-1a over the first length bytes of the open file; false if it ends before.
bool checksum(FILE *fp, uint64_t length, uint64_t *hash) {
  unsigned char buffer[1 << 16];
  uint64_t      h = 1469598103934665603ull, left = length;
  while (left > 0) {
    const size_t n = std::fread(buffer, 1, left < sizeof buffer ? (size_t)left : sizeof buffer, fp);
    if (n == 0) return false;
    for (size_t i = 0; i < n; ++i) h = (h ^ buffer[i]) * 1099511628211ull;
    left -= n;
  }
  *hash = h;
  return true;
}

} // namespace

bool CheckpointSeal(const std::string &path) {
  FILE *fp = std::fopen(path.c_str(), "rb+");
  if (!fp) return false;
  Seal seal{kSealMagic, 0, 0};
  bool ok = std::fseek(fp, 0, SEEK_END) == 0;
  if (ok) seal.length = (uint64_t)std::ftell(fp);
  ok = ok && std::fseek(fp, 0, SEEK_SET) == 0 && checksum(fp, seal.length, &seal.checksum);
  ok = ok && std::fseek(fp, 0, SEEK_END) == 0 && std::fwrite(&seal, sizeof seal, 1, fp) == 1;
  return std::fclose(fp) == 0 && ok;
}

std::string CheckpointSealProblem(const std::string &path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) return "it is a folder";
  FILE *fp = std::fopen(path.c_str(), "rb");
  if (!fp) return std::string("cannot open the file (") + std::strerror(errno) + ")";
  Seal        seal{};
  std::string problem;
  long        size = -1;
  if (std::fseek(fp, 0, SEEK_END) == 0) size = std::ftell(fp);
  if (size < (long)sizeof seal || std::fseek(fp, size - (long)sizeof seal, SEEK_SET) != 0 || std::fread(&seal, sizeof seal, 1, fp) != 1 ||
      seal.magic != kSealMagic)
    problem = "no checkpoint seal at its end (cut short, or not a slipwave checkpoint)";
  else if (seal.length != (uint64_t)size - sizeof seal)
    problem = "its length does not match its seal (cut short or extended)";
  else {
    uint64_t hash = 0;
    std::fseek(fp, 0, SEEK_SET);
    if (!checksum(fp, seal.length, &hash) || hash != seal.checksum) problem = "its checksum does not match (the file is damaged)";
  }
  std::fclose(fp);
  return problem;
}

} // namespace slipwave::app
