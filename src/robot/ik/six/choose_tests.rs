//! The chooser's third key: of solutions equally near, the one with more room to the limits.

use super::*;

/// Of two solutions equally near (the same time and the same distance from the previous pose),
/// the one with more room to the limits comes first, whatever the given order: from axis 6 at
/// 100 deg, 280 and -80 are both 180 deg away; 280 is 20 deg from the limit 300, -80 is 220.
#[test]
fn equally_near_solutions_are_ordered_by_room_to_the_limits() {
    let robot = Robot::irb1400();
    let ik = SixAxisIk::from_robot(&robot).expect("the IRB 1400 is a spherical-wrist arm");
    let conf = ConfData::from_array([0, 0, 0, 0]);
    let s = |axes_deg: Axes6| Solution { axes_deg, conf };
    let prev = [10.0, 20.0, 30.0, 40.0, 50.0, 100.0];
    let near_stop = s([10.0, 20.0, 30.0, 40.0, 50.0, 280.0]);
    let roomy = s([10.0, 20.0, 30.0, 40.0, 50.0, -80.0]);
    for given in [vec![near_stop, roomy], vec![roomy, near_stop]] {
        let mut v = given;
        ik.order_by_move(&mut v, Some(&prev));
        assert_eq!(v, vec![roomy, near_stop]);
    }
    // By hand, each axis's room (ranges 170, 70, -65..70, 150, 115, 300): 160, 50, 40, 110, 65
    // and 20 (near_stop) or 220 (roomy); smallest first, 20 against 40.
    assert_eq!(
        ik.rooms_deg(&near_stop.axes_deg),
        [20.0, 40.0, 50.0, 65.0, 110.0, 160.0]
    );
    assert_eq!(
        ik.rooms_deg(&roomy.axes_deg),
        [40.0, 50.0, 65.0, 110.0, 160.0, 220.0]
    );
    // The chooser on a real pose of both: the roomy turn of axis 6.
    let pose = robot.tool0(&roomy.axes_deg);
    let ok = |_: &Axes6| Ok::<(), String>(());
    let c = ik.choose(&pose, None, Some(&prev), ok).expect("ok");
    let diff = (0..6)
        .map(|k| (c.axes_deg[k] - roomy.axes_deg[k]).abs())
        .fold(0.0, f64::max);
    assert!(diff < 1e-9, "{c:?}");
}
