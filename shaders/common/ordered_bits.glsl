// A float as a uint whose unsigned order is the float's order (the sign bit set for positives,
// every bit flipped for negatives), so atomicMin/atomicMax on uints reduce floats. Read back in
// C++ with floatFromOrderedBits (app/gl/storage_blocks.h).
uint orderedBits(float f) {
  uint u = floatBitsToUint(f);
  return (u & 0x80000000u) != 0u ? ~u : u | 0x80000000u;
}
