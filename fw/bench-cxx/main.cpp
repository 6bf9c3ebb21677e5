/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief What drdc.hpp adds to the hot path: the quaternion product
 * through drdc::Quat's operator* beside the C call drdc_quat_mul(), in
 * one image, the same loop and the same operands.
 *
 * Prints fw/bench's lines (BENCH-CALIBRATE, BENCH <impl> <name> ...), so
 * tools/gates/bench.py's reader turns ticks into instructions per call
 * under QEMU -icount; tests/integration/test_cxx.py demands the wrapper
 * within 5 % of the C call.
 */
#include <drdc/drdc.hpp>

extern "C" {
#include "console.h"
#include "drdc_board.h"
}

namespace {

/* Calls per case and iterations of the calibration spin, as fw/bench. */
constexpr uint32_t calls = 4096u;
constexpr uint32_t spin = 1000000u;
constexpr uint32_t inputs = 256u;

drdc::Quat qa[inputs];
drdc::Quat qb[inputs];
volatile uint32_t sink;

/* Unit quaternions from pseudo-random Euler angles (xorshift32), made
 * by the library itself. */
void make_operands()
{
  uint32_t x = 2463534242u;
  auto next = [&x]() {
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    return x;
  };
  for (uint32_t k = 0u; k < inputs; ++k) {
    const drdc::Euler a{drdc::Angle::from_bam(next()),
                        drdc::Angle::from_bam(next() >> 2),
                        drdc::Angle::from_bam(next())};
    const drdc::Euler b{drdc::Angle::from_bam(next()),
                        drdc::Angle::from_bam(next() >> 2),
                        drdc::Angle::from_bam(next())};
    qa[k] = drdc::to_quat(a).value_or(drdc::Quat());
    qb[k] = drdc::to_quat(b).value_or(drdc::Quat());
  }
}

uint32_t fold(const drdc::Quat &q)
{
  return static_cast<uint32_t>(q.s() ^ q.x() ^ q.y() ^ q.z());
}

/* The empty loop: subtracted from every case. */
void loop_overhead(uint32_t n)
{
  uint32_t acc = 0u;
  for (uint32_t i = 0u; i < n; i++) {
    acc ^= i % inputs;
  }
  sink = acc;
}

/* The C call, as fw/bench times it: operands and result through
 * pointers, the status ignored. */
void quat_mul_c(uint32_t n)
{
  uint32_t acc = 0u;
  for (uint32_t i = 0u; i < n; i++) {
    const uint32_t k = i % inputs;
    drdc_quat_t r = {0, 0, 0, 0};
    (void)drdc_quat_mul(&qa[k].c(), &qb[k].c(), &r);
    acc ^= static_cast<uint32_t>(r.s ^ r.x ^ r.y ^ r.z);
  }
  sink = acc;
}

/* The wrapper: a drdc::result<drdc::Quat> whose value is read. */
void quat_mul_cxx(uint32_t n)
{
  uint32_t acc = 0u;
  for (uint32_t i = 0u; i < n; i++) {
    const uint32_t k = i % inputs;
    const drdc::result<drdc::Quat> r = qa[k] * qb[k];
    acc ^= fold(r.value());
  }
  sink = acc;
}

uint32_t elapsed(uint32_t start)
{
  return (bsp_ticks() - start) & bsp_ticks_mask;
}

void time_case(const char *impl, const char *name, const char *symbol,
               void (*run)(uint32_t))
{
  run(16u); /* warm-up: the same path as below */
  const uint32_t start = bsp_ticks();
  run(calls);
  const uint32_t ticks = elapsed(start);
  bsp_puts("BENCH ");
  bsp_puts(impl);
  bsp_putc(' ');
  bsp_puts(name);
  bsp_puts(" symbol=");
  bsp_puts(symbol);
  bsp_puts(" calls=");
  console_put_u64(calls);
  bsp_puts(" ticks=");
  console_put_u64(ticks);
  bsp_putc('\n');
}

} // namespace

int main()
{
  make_operands();
  bsp_ticks_start();
  bsp_puts("BENCH-TARGET ");
  bsp_puts(bsp_name);
  bsp_putc('\n');
  /* ticks per known number of instructions: spin(spin) - spin(0) */
  uint32_t start = bsp_ticks();
  bsp_spin(0u);
  const uint32_t empty = elapsed(start);
  start = bsp_ticks();
  bsp_spin(spin);
  bsp_puts("BENCH-CALIBRATE iterations=");
  console_put_u64(spin);
  bsp_puts(" per_iteration=");
  console_put_u64(bsp_spin_insns_per_iteration);
  bsp_puts(" ticks=");
  console_put_u64(elapsed(start) - empty);
  bsp_putc('\n');
  time_case("overhead", "loop", "-", loop_overhead);
  time_case("drdc", "quat_mul", "drdc_quat_mul", quat_mul_c);
  time_case("cxx", "quat_mul", "drdc_quat_mul", quat_mul_cxx);
  bsp_puts("BENCH-DONE\n");
  return 0;
}
