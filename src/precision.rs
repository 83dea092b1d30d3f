//! The one table of output precisions: how many decimals each kind of number has in the RAPID
//! module (joint values, header figures, the poses of robtargets, tooldata and wobjdata). The
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
/// The tool's mass in `PERS tooldata` (kg); also the cell's `tool.mass`.
pub const MASS_DECIMALS: usize = 3;

/// `10^decimals`, the scale of the rounding.
fn scale(decimals: usize) -> f64 {
    10f64.powi(decimals as i32)
}

/// `v` rounded to `decimals` decimals (half away from zero on the scaled value; may be `-0.0`).
pub fn round(v: f64, decimals: usize) -> f64 {
    let s = scale(decimals);
    (v * s).round() / s
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

    #[test]
    fn quantized_joints_have_no_negative_zero() {
        let q = quantize_joints([-0.0004, 12.3456, -7.0]);
        assert_eq!(q, [0.0, 12.346, -7.0]);
        assert!(q[0].is_sign_positive());
    }
}
