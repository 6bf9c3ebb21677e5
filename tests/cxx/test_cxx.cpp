/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Unity tests of drdc.hpp, the C++ layer: reference vectors,
 * literals against exact rationals, and each wrapper against its C call.
 */
#include <drdc/drdc.hpp>

#include <string.h>

#include "unity.h"

#include "geo/vectors_pose.h"
#include "orient/vectors_orient.h"
#include "time/vectors_time.h"

#include "test_cxx.h"

using namespace drdc::literals;

namespace {

drdc::Quat quat_of(const int32_t q[4])
{
  return drdc::Quat(q[0], q[1], q[2], q[3]);
}

void assert_quat(const int32_t expected[4], const drdc::Quat &q)
{
  TEST_ASSERT_EQUAL_INT32(expected[0], q.s());
  TEST_ASSERT_EQUAL_INT32(expected[1], q.x());
  TEST_ASSERT_EQUAL_INT32(expected[2], q.y());
  TEST_ASSERT_EQUAL_INT32(expected[3], q.z());
}

void assert_quat(const drdc_quat_t &expected, const drdc::Quat &q)
{
  const int32_t parts[4] = {expected.s, expected.x, expected.y, expected.z};
  assert_quat(parts, q);
}

/* Exact products (Python integers, tests/ref/gen_orient_quat.py), their
 * overflow statuses included, through operator*. */
void test_quat_product_matches_the_exact_vectors()
{
  const orient_mul_vector *tables[] = {orient_mul_vectors,
                                       orient_mul_edge_vectors};
  const size_t counts[] = {COUNT(orient_mul_vectors),
                           COUNT(orient_mul_edge_vectors)};

  for (size_t t = 0u; t < 2u; ++t) {
    for (size_t i = 0u; i < counts[t]; ++i) {
      const orient_mul_vector &v = tables[t][i];
      const drdc::result<drdc::Quat> p = quat_of(v.a) * quat_of(v.b);

      TEST_ASSERT_EQUAL_INT(v.status, p.code());
      if (v.status == DRDC_OK) {
        assert_quat(v.p, p.value());
      }
    }
  }
}

/* A chain passes the first error through: a product that overflows
 * (an edge vector with status DRDC_E_OVERFLOW) times anything. */
void test_quat_chain_keeps_the_first_error()
{
  const orient_mul_vector &bad = orient_mul_edge_vectors[1];
  const drdc::Quat one;

  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, bad.status);
  const drdc::result<drdc::Quat> r = quat_of(bad.a) * quat_of(bad.b) * one;
  TEST_ASSERT_FALSE(r.ok());
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, r.code());
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, (one * r).code());
  TEST_ASSERT_TRUE(r.value_or(one) == one);
}

/* q * conj(q) and conj(conj(q)) against the C calls, bit for bit. */
void test_conj_and_product_equal_the_c_calls()
{
  for (size_t i = 0u; i < COUNT(orient_euler_vectors); ++i) {
    const int32_t *c = orient_euler_vectors[i].q;
    const drdc_quat_t q = {c[0], c[1], c[2], c[3]};
    drdc_quat_t conj = {0, 0, 0, 0};
    drdc_quat_t product = {0, 0, 0, 0};

    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_quat_conj(&q, &conj));
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_quat_mul(&q, &conj, &product));
    const drdc::Quat w(q);
    const int32_t expected_conj[4] = {conj.s, conj.x, conj.y, conj.z};
    const int32_t expected_product[4] = {product.s, product.x, product.y,
                                         product.z};
    const drdc::result<drdc::Quat> wc = w.conj();
    TEST_ASSERT_EQUAL_INT(DRDC_OK, wc.code());
    assert_quat(expected_conj, wc.value());
    const drdc::result<drdc::Quat> back = wc.value().conj();
    TEST_ASSERT_EQUAL_INT(DRDC_OK, back.code());
    assert_quat(c, back.value());
    const drdc::result<drdc::Quat> p = w * w.conj();
    TEST_ASSERT_TRUE(p.ok());
    assert_quat(expected_product, p.value());
  }
}

/* A vector part of INT32_MIN (-2.0) has no negation in Q1.30: the
 * conjugate is DRDC_E_OVERFLOW (drdc_quat_conj), not a quaternion, and a
 * product with it passes the error on. */
void test_conj_of_int32_min_is_an_overflow()
{
  const drdc::Quat bad[3] = {drdc::Quat(0, INT32_MIN, 0, 0),
                             drdc::Quat(0, 0, INT32_MIN, 0),
                             drdc::Quat(0, 0, 0, INT32_MIN)};
  for (size_t i = 0u; i < COUNT(bad); ++i) {
    const drdc::result<drdc::Quat> c = bad[i].conj();
    TEST_ASSERT_FALSE(c.ok());
    TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, c.code());
    TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, (drdc::Quat() * c).code());
  }
  /* INT32_MIN as the scalar part is fine: only x, y, z are negated */
  const drdc::result<drdc::Quat> s = drdc::Quat(INT32_MIN, 1, 0, 0).conj();
  TEST_ASSERT_EQUAL_INT(DRDC_OK, s.code());
  TEST_ASSERT_TRUE(s.value() == drdc::Quat(INT32_MIN, -1, 0, 0));
}

/* Euler -> quaternion -> Euler through the wrappers equal the C calls;
 * the SciPy quaternions within the bound tests/orient asserts. */
void test_euler_conversions_equal_the_c_calls()
{
  for (size_t i = 0u; i < COUNT(orient_euler_vectors); ++i) {
    const orient_euler_vector &v = orient_euler_vectors[i];
    const drdc_euler_t e = {v.e[0], v.e[1], v.e[2]};
    drdc_quat_t q = {0, 0, 0, 0};
    drdc_euler_t back = {0u, 0u, 0u};

    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_quat_from_euler(&e, &q));
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_euler_from_quat(&q, &back));
    const drdc::result<drdc::Quat> wq = drdc::to_quat(drdc::Euler::from_c(e));
    TEST_ASSERT_TRUE(wq.ok());
    const int32_t expected[4] = {q.s, q.x, q.y, q.z};
    assert_quat(expected, wq.value());
    const drdc::result<drdc::Euler> we = drdc::to_euler(wq.value());
    TEST_ASSERT_TRUE(we.ok());
    TEST_ASSERT_EQUAL_UINT32(back.yaw, we.value().yaw.bam());
    TEST_ASSERT_EQUAL_UINT32(back.pitch, we.value().pitch.bam());
    TEST_ASSERT_EQUAL_UINT32(back.roll, we.value().roll.bam());
  }
}

/* Literals rounded once from the exact decimal: expected values are the
 * exact rationals (Python fractions) and the wrap of a binary angle. */
void test_degree_literals_round_exactly()
{
  /* 46.5 / 360 * 2^32 = 554766609 + 1/15 */
  constexpr drdc::Angle yaw = 46.5_deg;
  static_assert(yaw.bam() == 554766609u, "rounded down");
  TEST_ASSERT_EQUAL_UINT32(554766609u, yaw.bam());
  /* 2.2 / 360 * 2^32 = 26247022.364... */
  TEST_ASSERT_EQUAL_UINT32(26247022u, drdc::Angle(2.2_deg).bam());
  /* -0.8 / 360 * 2^32 = -9544371.77 -> -9544372, modulo 2^32 */
  TEST_ASSERT_EQUAL_UINT32(4285422924u, drdc::Angle(-0.8_deg).bam());
  TEST_ASSERT_EQUAL_UINT32(UINT32_C(1) << 30, drdc::Angle(90_deg).bam());
  TEST_ASSERT_EQUAL_UINT32(UINT32_C(3) << 30, drdc::Angle(-90_deg).bam());
  TEST_ASSERT_EQUAL_UINT32(UINT32_C(3) << 30, drdc::Angle(270_deg).bam());
  TEST_ASSERT_EQUAL_UINT32(0u, drdc::Angle(360_deg).bam());
  TEST_ASSERT_EQUAL_UINT32(UINT32_C(1) << 29, drdc::Angle(405_deg).bam());
  /* eighths of a turn are exact: the sums have no rounding to differ */
  TEST_ASSERT_TRUE(drdc::Angle(45_deg) + drdc::Angle(45_deg) ==
                   drdc::Angle(90_deg));
  TEST_ASSERT_TRUE(drdc::Angle(45_deg) - drdc::Angle(90_deg) ==
                   drdc::Angle(-45_deg));
  TEST_ASSERT_TRUE(drdc::Angle(180_deg) + drdc::Angle(180_deg) ==
                   drdc::Angle(0_deg));
  /* 3 600 000 000 000 nas a degree: 12 decimals are exact */
  TEST_ASSERT_EQUAL_INT64(INT64_C(180972000000000),
                          drdc::GeoAngle(50.27_deg).nas());
  TEST_ASSERT_EQUAL_INT64(INT64_C(-400212000000000),
                          drdc::GeoAngle(-111.17_deg).nas());
  TEST_ASSERT_EQUAL_INT64(3600, drdc::GeoAngle(0.000000001_deg).nas());
  /* 5e-13 degree = 1.8 nas -> 2; 1.25e-13 degree = 0.45 nas -> 0 */
  TEST_ASSERT_EQUAL_INT64(2, drdc::GeoAngle(0.0000000000005_deg).nas());
  TEST_ASSERT_EQUAL_INT64(-2, drdc::GeoAngle(-0.0000000000005_deg).nas());
  TEST_ASSERT_EQUAL_INT64(0, drdc::GeoAngle(0.000000000000125_deg).nas());
}

/* 2^-17 m = 0.00000762939453125 m exactly: half an LSB of Q.16, which
 * rounds away from zero; one digit less is below the half. */
void test_metre_literals_round_exactly()
{
  TEST_ASSERT_EQUAL_INT64(1, drdc::Length(0.00000762939453125_m).q47_16());
  TEST_ASSERT_EQUAL_INT64(-1, drdc::Length(-0.00000762939453125_m).q47_16());
  TEST_ASSERT_EQUAL_INT64(0, drdc::Length(0.0000076293945312_m).q47_16());
  TEST_ASSERT_EQUAL_INT32(1, drdc::LocalLength(0.00000762939453125_m).q15_16());
  /* 754.3 * 65536 = 49433804.8; 1.5 * 65536 = 98304 */
  TEST_ASSERT_EQUAL_INT64(INT64_C(49433805), drdc::Length(754.3_m).q47_16());
  TEST_ASSERT_EQUAL_INT32(-98304, drdc::LocalLength(-1.5_m).q15_16());
  /* the extremes of Q15.16 */
  TEST_ASSERT_EQUAL_INT32(INT32_MIN, drdc::LocalLength(-32768_m).q15_16());
  TEST_ASSERT_EQUAL_INT32(INT32_MAX,
                          drdc::LocalLength(32767.99998474121_m).q15_16());
  TEST_ASSERT_EQUAL_INT64(INT64_C(40000) * 65536,
                          drdc::Length(40000_m).q47_16());
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        drdc::to_local(drdc::Length(40000_m)).code());
  const drdc::result<drdc::LocalLength> near = drdc::to_local(1.5_m);
  TEST_ASSERT_TRUE(near.ok());
  TEST_ASSERT_EQUAL_INT32(98304, near.value().q15_16());
}

void assert_u128(uint64_t hi, uint64_t lo, drdc::detail::u128 v)
{
  TEST_ASSERT_EQUAL_UINT64(hi, v.hi);
  TEST_ASSERT_EQUAL_UINT64(lo, v.lo);
}

/* The literals' rounding division, worked out by hand, including
 * divisors above 2^127 (no literal reaches them, the function must not
 * care): there the remainder can have bit 127 set, and then twice it is
 * at least 2^128 > d, so the quotient rounds up. */
void test_div_round_rounds_half_away_from_zero()
{
  using drdc::detail::div_round;
  using drdc::detail::u128;
  const uint64_t top = uint64_t{1} << 63;
  /* 7 / 2 = 3.5 -> 4; 5 / 3 = 1.67 -> 2; 4 / 3 = 1.33 -> 1 */
  assert_u128(0u, 4u, div_round(u128{0u, 7u}, u128{0u, 2u}));
  assert_u128(0u, 2u, div_round(u128{0u, 5u}, u128{0u, 3u}));
  assert_u128(0u, 1u, div_round(u128{0u, 4u}, u128{0u, 3u}));
  /* 2^127 / (2^128 - 1) is a little above 1/2: 1 */
  assert_u128(0u, 1u, div_round(u128{top, 0u}, u128{UINT64_MAX, UINT64_MAX}));
  /* 2^127 / (2^127 + 1) is a little below 1: 1 */
  assert_u128(0u, 1u, div_round(u128{top, 0u}, u128{top, 1u}));
  /* (2^127 - 1) / (2^128 - 1) is a little below 1/2: 0 */
  assert_u128(
      0u, 0u,
      div_round(u128{top - 1u, UINT64_MAX}, u128{UINT64_MAX, UINT64_MAX}));
  /* (2^128 - 1) / (2^128 - 1) = 1 exactly */
  assert_u128(
      0u, 1u,
      div_round(u128{UINT64_MAX, UINT64_MAX}, u128{UINT64_MAX, UINT64_MAX}));
}

/* The literals agree with the C NMEA parser on the same decimal text
 * (nmea.h: degrees and minutes exact in nas, heights rounded to Q.16). */
void test_literals_agree_with_the_nmea_parser()
{
  static const char gga[] = "$GNGGA,170000.00,5016.20000,N,11110.20000,W,4,12,"
                            "0.7,754.3,M,-16.2,M,1.0,0001*66\r\n";
  const drdc::result<drdc::Nmea> s = drdc::Nmea::parse(gga, strlen(gga));

  static const char bad_sum[] = "$GNHDT,46.62,T*2E\r\n";

  TEST_ASSERT_TRUE(s.ok());
  TEST_ASSERT_TRUE(s.value().latitude() == drdc::GeoAngle(50.27_deg));
  TEST_ASSERT_TRUE(s.value().longitude() == drdc::GeoAngle(-111.17_deg));
  TEST_ASSERT_TRUE(s.value().altitude() == drdc::Length(754.3_m));
  TEST_ASSERT_EQUAL_INT(DRDC_E_CHECKSUM,
                        drdc::Nmea::parse(bad_sum, strlen(bad_sum)).code());
}

/* {W} -> {W-MGRS}: the text of GeoConvert (tests/ref/gen_geo_pose.py),
 * and every pose wrapper equal to its C call. */
void test_mgrs_pose_matches_geoconvert()
{
  for (size_t i = 0u; i < COUNT(pose_mgrs_vectors); ++i) {
    const pose_mgrs_vector &v = pose_mgrs_vectors[i];
    const drdc::WPose w{drdc::GeoAngle::from_nas(v.lon),
                        drdc::GeoAngle::from_nas(v.lat), 754.3_m, quat_of(v.q)};
    const drdc::result<drdc::WMGRSPose> m = drdc::to_mgrs(w, v.prec);

    TEST_ASSERT_TRUE(m.ok());
    TEST_ASSERT_EQUAL_STRING(v.mgrs, m.value().mgrs.c_str());
    TEST_ASSERT_TRUE(m.value().height == drdc::Length(754.3_m));

    const drdc_WPose_t cw = w.c();
    drdc_WMGRSPose_t cm;
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_pose_wmgrs_from_w(&cw, v.prec, &cm));
    assert_quat(cm.q, m.value().q);
  }
}

/* {W} -> {W-UTM} -> {W} and {W} -> {l} through the wrappers equal the C
 * calls; {le} -> {We} against the GeographicLib vectors' C results. */
void test_poses_equal_the_c_calls()
{
  const drdc::WPose first{
      -111.17_deg, 50.27_deg, 754.3_m,
      drdc::Quat(991756660, -15826452, 13727054, 410976062)};
  const drdc::WPose later{
      -111.169986667_deg, 50.270008333_deg, 754.4_m,
      drdc::Quat(986281899, -15022750, 15980188, 423896769)};
  const drdc::Length separation = -16.2_m;

  const drdc::result<drdc::WUTMPose> u = drdc::to_utm(later);
  const drdc_WPose_t cw = later.c();
  drdc_WUTMPose_t cu;
  TEST_ASSERT_EQUAL_INT(
      DRDC_OK, drdc_pose_wutm_from_w(&cw, DRDC_GEO_ZONE_STANDARD, &cu));
  TEST_ASSERT_TRUE(u.ok());
  TEST_ASSERT_EQUAL_INT32(12, u.value().utm.zone());
  TEST_ASSERT_TRUE(u.value().utm.north());
  TEST_ASSERT_EQUAL_INT64(cu.utm.easting, u.value().utm.easting().q47_16());
  TEST_ASSERT_EQUAL_INT64(cu.utm.northing, u.value().utm.northing().q47_16());
  assert_quat(cu.q, u.value().q);

  const drdc::result<drdc::WPose> back = drdc::to_w(u.value());
  drdc_WPose_t cback;
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_pose_w_from_wutm(&cu, &cback));
  TEST_ASSERT_TRUE(back.ok());
  TEST_ASSERT_EQUAL_INT64(cback.latitude, back.value().latitude.nas());
  TEST_ASSERT_EQUAL_INT64(cback.longitude, back.value().longitude.nas());

  const drdc::result<drdc::LPose> l = drdc::to_local(first, separation, later);
  const drdc_WPose_t cfirst = first.c();
  drdc_lPose_t cl;
  TEST_ASSERT_EQUAL_INT(
      DRDC_OK, drdc_pose_l_from_w(&cfirst, separation.q47_16(), &cw, &cl));
  TEST_ASSERT_TRUE(l.ok());
  TEST_ASSERT_EQUAL_INT32(cl.p.x, l.value().p.x.q15_16());
  TEST_ASSERT_EQUAL_INT32(cl.p.y, l.value().p.y.q15_16());
  TEST_ASSERT_EQUAL_INT32(cl.p.z, l.value().p.z.q15_16());

  for (size_t i = 0u; i < COUNT(pose_local_vectors); ++i) {
    const pose_local_vector &v = pose_local_vectors[i];
    const drdc_WePose_t ref = {
        v.ref[1], v.ref[0], v.ref[2], {v.ref_e[0], v.ref_e[1], v.ref_e[2]}};
    const drdc_lePose_t le = {{v.p[0], v.p[1], v.p[2]},
                              {v.e[0], v.e[1], v.e[2]}};
    drdc_WePose_t out;

    TEST_ASSERT_EQUAL_INT(DRDC_OK,
                          drdc_pose_we_from_le(&ref, v.sep, &le, &out));
    const drdc::result<drdc::WePose> w = drdc::to_global(
        drdc::WePose::from_c(ref), drdc::Length::from_q47_16(v.sep),
        drdc::LePose::from_c(le));
    TEST_ASSERT_TRUE(w.ok());
    TEST_ASSERT_EQUAL_INT64(out.latitude, w.value().latitude.nas());
    TEST_ASSERT_EQUAL_INT64(out.longitude, w.value().longitude.nas());
    TEST_ASSERT_EQUAL_INT64(out.height, w.value().height.q47_16());
    TEST_ASSERT_EQUAL_UINT32(out.e.yaw, w.value().e.yaw.bam());
  }
}

/* {We} -> {We-MGRS}: GeoConvert's text again; the square back to {W}
 * and {We} (its centre) and {We-UTM} -> {We}, each equal to its C
 * call. */
void test_mgrs_and_utm_back_to_global()
{
  for (size_t i = 0u; i < COUNT(pose_mgrs_vectors); i += 7u) {
    const pose_mgrs_vector &v = pose_mgrs_vectors[i];
    const drdc::Euler e{drdc::Angle::from_bam(v.yaw), 11_deg, 22_deg};
    const drdc::WePose we{drdc::GeoAngle::from_nas(v.lon),
                          drdc::GeoAngle::from_nas(v.lat), 754.3_m, e};
    const drdc::result<drdc::WeMGRSPose> me = drdc::to_mgrs(we, v.prec);
    TEST_ASSERT_TRUE(me.ok());
    TEST_ASSERT_EQUAL_STRING(v.mgrs, me.value().mgrs.c_str());

    const drdc::WMGRSPose m{me.value().mgrs, -3_m, quat_of(v.q)};
    const drdc_WMGRSPose_t cm = m.c();
    drdc_WPose_t cw;
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_pose_w_from_wmgrs(&cm, &cw));
    const drdc::result<drdc::WPose> w = drdc::to_w(m);
    TEST_ASSERT_TRUE(w.ok());
    TEST_ASSERT_EQUAL_INT64(cw.latitude, w.value().latitude.nas());
    TEST_ASSERT_EQUAL_INT64(cw.longitude, w.value().longitude.nas());
    TEST_ASSERT_EQUAL_INT64(cw.height, w.value().height.q47_16());
    assert_quat(cw.q, w.value().q);

    const drdc_WeMGRSPose_t cme = me.value().c();
    drdc_WePose_t cwe;
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_pose_we_from_wemgrs(&cme, &cwe));
    const drdc::result<drdc::WePose> back = drdc::to_we(me.value());
    TEST_ASSERT_TRUE(back.ok());
    TEST_ASSERT_EQUAL_INT64(cwe.latitude, back.value().latitude.nas());
    TEST_ASSERT_EQUAL_UINT32(cwe.e.yaw, back.value().e.yaw.bam());

    const drdc::result<drdc::WeUTMPose> u = drdc::to_utm(we);
    TEST_ASSERT_TRUE(u.ok());
    const drdc_WeUTMPose_t cu = u.value().c();
    drdc_WePose_t cfrom;
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_pose_we_from_weutm(&cu, &cfrom));
    const drdc::result<drdc::WePose> from = drdc::to_we(u.value());
    TEST_ASSERT_TRUE(from.ok());
    TEST_ASSERT_EQUAL_INT64(cfrom.latitude, from.value().latitude.nas());
    TEST_ASSERT_EQUAL_INT64(cfrom.longitude, from.value().longitude.nas());
    TEST_ASSERT_EQUAL_UINT32(cfrom.e.yaw, from.value().e.yaw.bam());
  }
}

/* {We} -> {le} and {le} -> {l} through the wrappers equal the C calls,
 * on the GeographicLib vectors' poses. */
void test_local_euler_poses_equal_the_c_calls()
{
  for (size_t i = 0u; i < COUNT(pose_local_vectors); i += 5u) {
    const pose_local_vector &v = pose_local_vectors[i];
    const drdc_WePose_t ref = {
        v.ref[1], v.ref[0], v.ref[2], {v.ref_e[0], v.ref_e[1], v.ref_e[2]}};
    const drdc_WePose_t there = {
        v.lon, v.lat, v.height, {v.out_e[0], v.out_e[1], v.out_e[2]}};
    drdc_lePose_t cle;
    drdc_lPose_t cl;

    TEST_ASSERT_EQUAL_INT(DRDC_OK,
                          drdc_pose_le_from_we(&ref, v.sep, &there, &cle));
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_pose_l_from_le(&cle, &cl));
    const drdc::result<drdc::LePose> le = drdc::to_local(
        drdc::WePose::from_c(ref), drdc::Length::from_q47_16(v.sep),
        drdc::WePose::from_c(there));
    TEST_ASSERT_TRUE(le.ok());
    TEST_ASSERT_EQUAL_INT32(cle.p.x, le.value().p.x.q15_16());
    TEST_ASSERT_EQUAL_INT32(cle.p.y, le.value().p.y.q15_16());
    TEST_ASSERT_EQUAL_INT32(cle.p.z, le.value().p.z.q15_16());
    TEST_ASSERT_EQUAL_UINT32(cle.e.roll, le.value().e.roll.bam());
    const drdc::result<drdc::LPose> l = drdc::to_quat(le.value());
    TEST_ASSERT_TRUE(l.ok());
    assert_quat(cl.q, l.value().q);
  }
}

/* Errors come back as statuses: a latitude beyond 90 degrees, a zero
 * quaternion. */
void test_errors_are_statuses()
{
  const drdc::WPose pole{0_deg, 91_deg, 0_m, drdc::Quat()};
  const drdc::result<drdc::WUTMPose> u = drdc::to_utm(pole);

  TEST_ASSERT_FALSE(u.ok());
  TEST_ASSERT_FALSE(static_cast<bool>(u));
  TEST_ASSERT_EQUAL_INT(DRDC_E_LATITUDE, u.code());
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN,
                        drdc::Quat(0, 0, 0, 0).normalized().code());
  TEST_ASSERT_EQUAL_STRING("DRDC_E_LATITUDE", drdc_status_name(u.code()));
}

/* Leap seconds (tests/ref/gen_time_scales.py, ERFA): across 1972-06-30's
 * leap second, +1 s from 23:59:59 is 23:59:60 (nsec >= 1e9), +2 s is the
 * next midnight; time order and differences count it. */
void test_time_points_across_a_leap_second()
{
  const time_special *before = nullptr;
  const time_special *leap = nullptr;
  for (size_t i = 0u; i < COUNT(time_specials); ++i) {
    const time_special &v = time_specials[i];
    if ((v.year == 1972) && (v.month == 6) && (v.second == 59) &&
        (v.nsec == 0) && (before == nullptr)) {
      before = &v;
    }
    if ((v.year == 1972) && (v.month == 6) && (v.second == 60) &&
        (v.nsec == 1000000000) && (leap == nullptr)) {
      leap = &v;
    }
  }
  TEST_ASSERT_NOT_NULL(before);
  TEST_ASSERT_NOT_NULL(leap);
  const drdc::UtcTime t0(drdc_time_t{before->utc_sec, before->nsec});
  const drdc::UtcTime t1(drdc_time_t{leap->utc_sec, leap->nsec});
  const drdc::result<drdc::UtcTime> plus1 = t0 + drdc::Duration::seconds(1);
  const drdc::result<drdc::UtcTime> plus2 = t0 + drdc::Duration::seconds(2);

  TEST_ASSERT_TRUE(plus1.ok());
  TEST_ASSERT_TRUE(plus1.value() == t1);
  TEST_ASSERT_TRUE(plus2.ok());
  TEST_ASSERT_EQUAL_INT64(static_cast<int64_t>(before->utc_sec) + 1,
                          plus2.value().c().sec);
  TEST_ASSERT_EQUAL_INT32(0, plus2.value().c().nsec);
  TEST_ASSERT_TRUE(t0 < t1);
  TEST_ASSERT_TRUE(t1 < plus2.value());
  TEST_ASSERT_TRUE(plus2.value() > t1);
  const drdc::result<drdc::Duration> d = plus2.value() - t0;
  TEST_ASSERT_TRUE(d.ok());
  TEST_ASSERT_TRUE(d.value() == drdc::Duration::seconds(2));
  const drdc::result<drdc::UtcTime> minus =
      plus2.value() - drdc::Duration::nanoseconds(1);
  TEST_ASSERT_TRUE(minus.ok());
  TEST_ASSERT_EQUAL_INT32(1999999999, minus.value().c().nsec);
}

/* GPS time: the epoch 1980-01-06 is week 0, and 2017-01-01T00:00:00Z is
 * 13 510 days = 1930 weeks later with GPS - UTC = 18 s (IERS Bulletin
 * C). Durations carry into the week. */
void test_gps_time()
{
  const drdc::result<drdc::UtcTime> epoch =
      drdc::UtcTime::parse("1980-01-06T00:00:00Z");
  const drdc::result<drdc::UtcTime> y2017 =
      drdc::UtcTime::parse("2017-01-01T00:00:00Z");

  TEST_ASSERT_TRUE(epoch.ok());
  TEST_ASSERT_TRUE(y2017.ok());
  const drdc::result<drdc::GpsTime> g0 = drdc::GpsTime::from_utc(epoch.value());
  const drdc::result<drdc::GpsTime> g = drdc::GpsTime::from_utc(y2017.value());
  TEST_ASSERT_TRUE(g0.ok());
  TEST_ASSERT_EQUAL_INT32(0, g0.value().week());
  TEST_ASSERT_EQUAL_INT32(0, g0.value().tow());
  TEST_ASSERT_TRUE(g.ok());
  TEST_ASSERT_EQUAL_INT32(1930, g.value().week());
  TEST_ASSERT_EQUAL_INT32(18, g.value().tow());
  const drdc::result<drdc::GpsTime> back =
      g.value() - drdc::Duration::seconds(19);
  TEST_ASSERT_TRUE(back.ok());
  TEST_ASSERT_EQUAL_INT32(1929, back.value().week());
  TEST_ASSERT_EQUAL_INT32(604799, back.value().tow());
  TEST_ASSERT_TRUE(back.value() < g.value());
  const drdc::result<drdc::UtcTime> u = g.value().utc();
  TEST_ASSERT_TRUE(u.ok());
  TEST_ASSERT_TRUE(u.value() == y2017.value());
  TEST_ASSERT_EQUAL_INT(DRDC_E_MONTH,
                        drdc::UtcTime::parse("2017-13-01T00:00:00Z").code());
}

/* Durations keep nanoseconds in 0..999 999 999, negative ones too, and
 * refuse to wrap: INT64_MIN nanoseconds is -9 223 372 037 s + 145 224 192
 * ns exactly. */
void test_durations()
{
  constexpr drdc::Duration d = drdc::Duration::nanoseconds(-1);
  static_assert((d.sec() == -1) && (d.nsec() == 999999999), "floor");
  const drdc::Duration low = drdc::Duration::nanoseconds(INT64_MIN);
  TEST_ASSERT_EQUAL_INT64(INT64_C(-9223372037), low.sec());
  TEST_ASSERT_EQUAL_INT32(145224192, low.nsec());
  const drdc::result<drdc::Duration> one =
      drdc::Duration::nanoseconds(400000000) +
      drdc::Duration::nanoseconds(600000000);
  TEST_ASSERT_TRUE(one.ok());
  TEST_ASSERT_TRUE(one.value() == drdc::Duration::seconds(1));
  const drdc::result<drdc::Duration> minus_one = -drdc::Duration::seconds(1);
  TEST_ASSERT_TRUE(minus_one.ok());
  TEST_ASSERT_TRUE(minus_one.value() < drdc::Duration());
  const drdc::result<drdc::Duration> back = -d;
  TEST_ASSERT_TRUE(back.ok());
  TEST_ASSERT_TRUE(back.value() == drdc::Duration::nanoseconds(1));
  /* a chain of sums: 1 s - 1 ns + 1 ns */
  const drdc::result<drdc::Duration> chain = drdc::Duration::seconds(1) -
                                             drdc::Duration::nanoseconds(1) +
                                             drdc::Duration::nanoseconds(1);
  TEST_ASSERT_TRUE(chain.ok());
  TEST_ASSERT_TRUE(chain.value() == drdc::Duration::seconds(1));

  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        (drdc::Duration::seconds(INT64_MAX) +
                         drdc::Duration::nanoseconds(1000000000))
                            .code());
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        (drdc::Duration::seconds(INT64_MAX) +
                         drdc::Duration::nanoseconds(999999999) +
                         drdc::Duration::nanoseconds(1))
                            .code());
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        (-drdc::Duration::seconds(INT64_MIN)).code());
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, (drdc::Duration::seconds(INT64_MIN) -
                                          drdc::Duration::nanoseconds(1))
                                             .code());
  /* differences at the edges of int64_t seconds, subtracted directly:
   * -1 s - (-2^63 s) = 2^63 - 1 s fits, 0 s - (-2^63 s) = 2^63 s does
   * not */
  const drdc::result<drdc::Duration> top =
      drdc::Duration::seconds(-1) - drdc::Duration::seconds(INT64_MIN);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, top.code());
  TEST_ASSERT_EQUAL_INT64(INT64_MAX, top.value().sec());
  TEST_ASSERT_EQUAL_INT32(0, top.value().nsec());
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_OVERFLOW,
      (drdc::Duration() - drdc::Duration::seconds(INT64_MIN)).code());
  /* 0 - (-2^63 s + 1 ns) = 2^63 s - 1 ns = (2^63 - 1) s + 999 999 999 ns,
   * only with the borrow taken before the seconds */
  const drdc::result<drdc::Duration> top_ns =
      drdc::Duration() - drdc::Duration::of(INT64_MIN, 1).value();
  TEST_ASSERT_EQUAL_INT(DRDC_OK, top_ns.code());
  TEST_ASSERT_EQUAL_INT64(INT64_MAX, top_ns.value().sec());
  TEST_ASSERT_EQUAL_INT32(999999999, top_ns.value().nsec());
  /* (-2^63 s + 1 ns) - 1 ns = -2^63 s fits; 1 ns less does not */
  const drdc::result<drdc::Duration> bottom =
      drdc::Duration::of(INT64_MIN, 1).value() - drdc::Duration::nanoseconds(1);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, bottom.code());
  TEST_ASSERT_EQUAL_INT64(INT64_MIN, bottom.value().sec());
  TEST_ASSERT_EQUAL_INT32(0, bottom.value().nsec());
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        (drdc::Duration::of(INT64_MIN, 1).value() -
                         drdc::Duration::nanoseconds(2))
                            .code());
  /* 2^63 - 1 s - (-1 ns) = 2^63 - 1 s + 1 ns fits; from the last
   * nanosecond of that second it does not */
  const drdc::result<drdc::Duration> top_plus =
      drdc::Duration::seconds(INT64_MAX) - drdc::Duration::nanoseconds(-1);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, top_plus.code());
  TEST_ASSERT_EQUAL_INT64(INT64_MAX, top_plus.value().sec());
  TEST_ASSERT_EQUAL_INT32(1, top_plus.value().nsec());
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        (drdc::Duration::of(INT64_MAX, 999999999).value() -
                         drdc::Duration::nanoseconds(-1))
                            .code());

  TEST_ASSERT_EQUAL_INT(DRDC_E_NANOSECOND,
                        drdc::Duration::of(0, 1000000000).code());
  TEST_ASSERT_EQUAL_INT(DRDC_E_NANOSECOND, drdc::Duration::of(0, -1).code());
  TEST_ASSERT_TRUE(drdc::Duration::of(-1, 999999999).value() == d);

  /* an instant that far away: an error, not a wrapped time */
  const drdc::UtcTime t(drdc_time_t{0, 0});
  TEST_ASSERT_FALSE((t + drdc::Duration::seconds(INT64_MAX)).ok());
  TEST_ASSERT_FALSE((t - drdc::Duration::seconds(INT64_MIN)).ok());
}

/* An instant on the built-in table's expiry day, 2027-06-28 00:00:00
 * UTC (20 997 days after 1970-01-01: 57 years with 14 leap days, then
 * 178 days into 2027), converts with DRDC_W_LEAP_EXPIRED; a span or a sum
 * that starts there keeps the warning even when it ends before the
 * expiry. No leap second lies between the two instants (the last is
 * 2017-01-01), so the span is one day exactly. */
void test_leap_expiry_warning_carries()
{
  const int64_t expiry = INT64_C(20997) * 86400;
  const drdc::UtcTime late(drdc_time_t{expiry, 0});
  const drdc::UtcTime early(drdc_time_t{expiry - 86400, 0});
  TEST_ASSERT_EQUAL_INT(DRDC_W_LEAP_EXPIRED, late.tai().code());
  TEST_ASSERT_EQUAL_INT(DRDC_OK, early.tai().code());

  const drdc::result<drdc::Duration> span = late - early;
  TEST_ASSERT_EQUAL_INT(DRDC_W_LEAP_EXPIRED, span.code());
  TEST_ASSERT_TRUE(span.value() == drdc::Duration::seconds(86400));
  const drdc::result<drdc::Duration> back = early - late;
  TEST_ASSERT_EQUAL_INT(DRDC_W_LEAP_EXPIRED, back.code());
  TEST_ASSERT_TRUE(back.value() == drdc::Duration::seconds(-86400));
  const drdc::result<drdc::Duration> none = early - early;
  TEST_ASSERT_EQUAL_INT(DRDC_OK, none.code());

  const drdc::result<drdc::UtcTime> day_before =
      late - drdc::Duration::seconds(86400);
  TEST_ASSERT_EQUAL_INT(DRDC_W_LEAP_EXPIRED, day_before.code());
  TEST_ASSERT_TRUE(day_before.value() == early);
  const drdc::result<drdc::UtcTime> plus =
      late.plus(drdc::Duration::seconds(-1));
  TEST_ASSERT_EQUAL_INT(DRDC_W_LEAP_EXPIRED, plus.code());
  TEST_ASSERT_EQUAL_INT64(expiry - 1, plus.value().c().sec);
}

#if defined(__cpp_exceptions)
/* Where the compiler has exceptions, value_or_throw() throws the status. */
void test_value_or_throw_throws_the_status()
{
  const drdc::result<drdc::Quat> zero = drdc::Quat(0, 0, 0, 0).normalized();
  drdc::status caught = DRDC_OK;
  try {
    (void)zero.value_or_throw();
  } catch (const drdc::error &e) {
    caught = e.code;
    TEST_ASSERT_EQUAL_STRING("DRDC_E_DOMAIN", e.what());
  }
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN, caught);
  TEST_ASSERT_TRUE(drdc::Quat(0, 0, 0, 1).normalized().value_or_throw() ==
                   drdc::Quat(0, 0, 0, DRDC_Q1_30_ONE));
}
#endif

} // namespace

void suite_cxx(void)
{
  UnitySetTestFile(__FILE__);
  RUN_TEST(test_quat_product_matches_the_exact_vectors);
  RUN_TEST(test_quat_chain_keeps_the_first_error);
  RUN_TEST(test_conj_and_product_equal_the_c_calls);
  RUN_TEST(test_conj_of_int32_min_is_an_overflow);
  RUN_TEST(test_euler_conversions_equal_the_c_calls);
  RUN_TEST(test_degree_literals_round_exactly);
  RUN_TEST(test_metre_literals_round_exactly);
  RUN_TEST(test_div_round_rounds_half_away_from_zero);
  RUN_TEST(test_literals_agree_with_the_nmea_parser);
  RUN_TEST(test_mgrs_pose_matches_geoconvert);
  RUN_TEST(test_poses_equal_the_c_calls);
  RUN_TEST(test_mgrs_and_utm_back_to_global);
  RUN_TEST(test_local_euler_poses_equal_the_c_calls);
  RUN_TEST(test_errors_are_statuses);
  RUN_TEST(test_time_points_across_a_leap_second);
  RUN_TEST(test_gps_time);
  RUN_TEST(test_durations);
  RUN_TEST(test_leap_expiry_warning_carries);
#if defined(__cpp_exceptions)
  RUN_TEST(test_value_or_throw_throws_the_status);
#endif
}
