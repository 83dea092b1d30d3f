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
/// The tool's mass in `PERS tooldata` (kg); also the cell's `tool.mass`.
pub const MASS_DECIMALS: usize = 3;

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
