#pragma once
// The header of a PLY file (Turk's polygon file format): the format line, the elements in
// file order with their counts and properties. Parsed strictly; ply_reader.hpp reads the body.
//
// Accepted: the first line `ply` (ending "\n" or "\r\n", as every header line may);
// `format ascii|binary_little_endian|binary_big_endian 1.0`; `comment ...` and
// `obj_info ...` lines anywhere; `element NAME COUNT`; `property TYPE NAME` and
// `property list COUNT_TYPE ITEM_TYPE NAME` with the types char/int8, uchar/uint8,
// short/int16, ushort/uint16, int/int32, uint/uint32, float/float32, double/float64;
// `end_header`. Anything else is an InputError naming the header line.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace ccd::cloth {

enum class PlyFormat : std::uint8_t { Ascii, BinaryLittleEndian, BinaryBigEndian };

enum class PlyType : std::uint8_t { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

/// Bytes of one binary value of the type.
std::size_t ply_type_size(PlyType t);
bool ply_type_is_integer(PlyType t);
/// The name a header spells (the short one: "uchar", "float", ...).
const char* ply_type_name(PlyType t);

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::Float32;  ///< of the value, or of each item of a list
  bool list = false;
  PlyType count_type = PlyType::UInt8;  ///< of a list's count
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
};

struct PlyHeader {
  PlyFormat format = PlyFormat::Ascii;
  std::vector<PlyElement> elements;
  std::size_t body_offset = 0;  ///< the first byte after the end_header line
  std::size_t lines = 0;        ///< lines of the header, end_header included
};

/// Parses the header at the start of `bytes`. Throws InputError naming `file`: an empty
/// file, a first line other than `ply`, no end_header line, an unknown keyword, format or
/// type, a malformed count, a property before any element, a property named twice in one
/// element, a list whose count type is not an integer type.
PlyHeader parse_ply_header(std::string_view bytes, const std::string& file);

/// True when `bytes` start with the PLY magic line ("ply\n" or "ply\r\n").
bool has_ply_magic(std::string_view bytes);

}  // namespace ccd::cloth
