// Seeded pseudo-random numbers, so that a case file is a pure function of its
// seed (Math.random cannot be seeded). Quality needs are modest: we only want
// varied, reproducible test inputs.

// One step of a 32-bit integer hash (multiply-xorshift); used to spread the
// user's seed over the generator state so that nearby seeds give unrelated
// streams.
function mix32(h) {
  h = Math.imul(h ^ (h >>> 16), 0x85ebca6b);
  h = Math.imul(h ^ (h >>> 13), 0xc2b2ae35);
  return (h ^ (h >>> 16)) >>> 0;
}

export class Prng {
  constructor(seed) {
    if (!Number.isSafeInteger(seed) || seed < 0) {
      throw new Error(`seed must be a non-negative integer, got ${seed}`);
    }
    // Fold the high bits in too, so seeds above 2^32 still differ.
    let h = (seed % 0x100000000) ^ mix32(Math.floor(seed / 0x100000000));
    this.state = [];
    for (let i = 0; i < 4; ++i) {
      h = (h + 0x6d2b79f5) >>> 0;
      this.state.push(mix32(h));
    }
    if (this.state.every((w) => w === 0)) this.state[0] = 1;  // xorshift's one bad state
  }

  // Marsaglia's xorshift128 on four 32-bit words.
  nextU32() {
    const s = this.state;
    let t = s[3];
    t ^= t << 11;
    t ^= t >>> 8;
    s[3] = s[2];
    s[2] = s[1];
    s[1] = s[0];
    s[0] = (t ^ s[0] ^ (s[0] >>> 19)) >>> 0;
    return s[0];
  }

  // Uniform in [0, 1) with 53 random bits.
  uniform() {
    const hi = this.nextU32() >>> 11;  // 21 bits
    const lo = this.nextU32();         // 32 bits
    return (hi * 0x100000000 + lo) / 2 ** 53;
  }

  range(lo, hi) {
    return lo + (hi - lo) * this.uniform();
  }

  // A coefficient in [-1, 1] that float represents exactly, so the float and
  // double C++ tests start from identical inputs.
  coefficient() {
    return Math.fround(this.range(-1, 1));
  }

  chance(p) {
    return this.uniform() < p;
  }
}
