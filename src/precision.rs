//! The one table of output precisions: how many decimals each kind of number has in the RAPID
//! module (joint values, header figures, the poses of robtargets, tooldata and wobjdata), in the
//! JSON report (`--report`, which states the module's numbers with the module's decimals) and in
//! the preview page's scene (`--html`). The
//! cell validation refuses input finer than what the module can state (so every cell value
//! appears in the module exactly as given; quaternions excepted, which are normalised), the
//! planner rounds computed joint values to it before proving them (so what is proven is what is
//! written), and the renderer formats with it. A leaf: it knows nothing of cells, plans or text.

/// Joint values in `CONST jointtarget` (deg); also the cell's joint values and `robot.wrist`.
pub const JOINT_DECIMALS: usize = 3;
/// Lengths in the header: clearance, base position, min clearance (mm); also `robot.base`.
pub const LENGTH_DECIMALS: usize = 1;
/// The grid spacing in the header (deg).
pub const GRID_DECIMALS: usize = 3;
/// The base yaw in the header (deg); also `robot.yaw`.
pub const YAW_DECIMALS: usize = 3;
/// The estimated manipulation time in the header (s).
pub const TIME_DECIMALS: usize = 2;
/// Positions in `CONST robtarget`, `PERS tooldata` (tframe, cog) and `PERS wobjdata` (uframe),
/// mm; also the cell's robtarget positions, `tool.tframe`, `tool.cog` and `wobj.uframe`.
pub const POSITION_DECIMALS: usize = 3;
/// Quaternion components `[q1, q2, q3, q4]` in the module. The cell's quaternions are
/// normalised when read (any number of decimals); the module writes the normalised values to
/// this many decimals, as RobotStudio does, so their norm is 1 within 2e-9.
pub const QUATERNION_DECIMALS: usize = 9;
/// The tool's mass in `PERS tooldata` and a load's in `PERS loaddata` (kg); also the cell's
/// `tool.mass` and `loads` masses.
pub const MASS_DECIMALS: usize = 3;
/// The seconds of `WaitTime` (s); also the cell's `wait_time` actions.
pub const WAIT_TIME_DECIMALS: usize = 3;

// ---- the JSON report (`--report`): the module's decimals, so that both state the same numbers ----

/// Joint values in the report (deg): as in the module.
pub const REPORT_JOINT_DECIMALS: usize = JOINT_DECIMALS;
/// Positions in the report (TCP, wrist centre, base; mm): as robtargets in the module.
pub const REPORT_POSITION_DECIMALS: usize = POSITION_DECIMALS;
/// Clearances in the report (mm): as the header's min clearance (a certified lower bound within
/// 0.05 mm, so a finer figure would claim more than is known).
pub const REPORT_CLEARANCE_DECIMALS: usize = LENGTH_DECIMALS;
/// Times in the report (s): as the header's estimated time.
pub const REPORT_TIME_DECIMALS: usize = TIME_DECIMALS;
/// The grid spacing and the yaw in the report (deg): as in the header.
pub const REPORT_GRID_DECIMALS: usize = GRID_DECIMALS;
pub const REPORT_YAW_DECIMALS: usize = YAW_DECIMALS;

// ---- the preview page's scene (`--html`), chosen by each JSON key's unit suffix ----

/// Lengths in millimetres (`_mm`): 0.001 mm.
pub const PREVIEW_MM_DECIMALS: usize = 3;
/// Times in seconds (`_s`): 1 ms.
pub const PREVIEW_SECONDS_DECIMALS: usize = 3;
/// Angles in degrees (`_deg`).
pub const PREVIEW_DEG_DECIMALS: usize = 3;
/// Quaternion components (`_wxyz`): 1e-4, under 0.02 deg, invisible on a screen.
pub const PREVIEW_QUAT_DECIMALS: usize = 4;
/// Any other non-integer number of the scene (none today).
pub const PREVIEW_OTHER_DECIMALS: usize = 6;

/// `10^decimals`, the scale of the rounding.
fn scale(decimals: usize) -> f64 {
    10f64.powi(decimals as i32)
}

/// `x.round()` (half away from zero), bit for bit, without the call to the library's `round`
/// that a generic x86-64 build makes (no SSE4.1 rounding instruction): the tool looks of a leg
/// round six values each (`plan::leg`). Below 2^52 in magnitude the truncation through `i64` is
/// exact, and so is `x - t`; beyond, every float is an integer already (or NaN or infinite).
#[inline]
pub fn round_half_away(x: f64) -> f64 {
    const INTEGRAL: f64 = 4_503_599_627_370_496.0; // 2^52
    if x.is_nan() || x.abs() >= INTEGRAL {
        return x;
    }
    let t = (x as i64) as f64;
    let r = x - t;
    let t = if r >= 0.5 {
        t + 1.0
    } else if r <= -0.5 {
        t - 1.0
    } else {
        t
    };
    t.copysign(x)
}

/// `v` rounded to `decimals` decimals (half away from zero on the scaled value; may be `-0.0`).
#[inline]
pub fn round(v: f64, decimals: usize) -> f64 {
    let s = scale(decimals);
    round_half_away(v * s) / s
}

/// Whether `v` needs more than `decimals` decimals (beyond a relative 1e-9, the slack of the
/// binary representation of a decimal literal).
pub fn exceeds(v: f64, decimals: usize) -> bool {
    (round(v, decimals) - v).abs() > 1e-9 * v.abs().max(1.0)
}

/// Joint values rounded to the written precision ([`JOINT_DECIMALS`]), never `-0.0`: the values
/// the planner proves and the module states.
pub fn quantize_joints<const N: usize>(a: [f64; N]) -> [f64; N] {
    a.map(|x| {
        let r = round(x, JOINT_DECIMALS);
        if r == 0.0 {
            0.0
        } else {
            r
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rounding_and_the_decimals_test_agree() {
        assert_eq!(round(1.23456, 3), 1.235);
        assert_eq!(round(-2.25, 1), -2.3);
        assert!(!exceeds(30.125, JOINT_DECIMALS) && exceeds(30.1255, JOINT_DECIMALS));
        assert!(!exceeds(-850.0, LENGTH_DECIMALS) && exceeds(2.25, LENGTH_DECIMALS));
        // A decimal literal is not exact in binary; the slack accepts it.
        assert!(!exceeds(0.1 + 0.2, 1));
    }

    /// `round_half_away` is `f64::round` bit for bit: halves, neighbours of halves, signed
    /// zeros, the edges of the exact range, infinities and NaN, and random values of every
    /// magnitude. Fails if the halves went to even, the sign of a zero result were lost, or
    /// large values were truncated.
    #[test]
    fn round_half_away_is_the_library_round_bit_for_bit() {
        let same = |x: f64| {
            let (a, b) = (round_half_away(x), x.round());
            assert!(
                a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan()),
                "{x:e}: {a:e} vs {b:e}"
            );
        };
        let p52 = 4_503_599_627_370_496.0f64;
        for x in [
            0.0,
            -0.0,
            0.5,
            -0.5,
            1.5,
            2.5,
            -2.5,
            0.49999999999999994,
            -0.49999999999999994,
            p52,
            -p52,
            p52 - 0.5,
            -(p52 - 0.5),
            p52 * 2.0 + 2.0,
            1e300,
            f64::MIN_POSITIVE,
            -f64::MIN_POSITIVE,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
        ] {
            same(x);
            same(f64::from_bits(x.to_bits().wrapping_add(1)));
            same(f64::from_bits(x.to_bits().wrapping_sub(1)));
        }
        let mut s = 0x9e37_79b9_7f4a_7c15u64;
        for _ in 0..200_000 {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            // Any sign, exponents from 2^-30 to 2^60, any mantissa; and halves of integers.
            let e = (s >> 53) % 90;
            let x = f64::from_bits(((1023 + e - 30) << 52) | (s & ((1 << 52) - 1)));
            let x = if s & (1 << 63) != 0 { -x } else { x };
            same(x);
            same((x * 2.0).trunc() * 0.5);
        }
    }

    #[test]
    fn quantized_joints_have_no_negative_zero() {
        let q = quantize_joints([-0.0004, 12.3456, -7.0]);
        assert_eq!(q, [0.0, 12.346, -7.0]);
        assert!(q[0].is_sign_positive());
    }
}
