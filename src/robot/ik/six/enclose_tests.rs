//! Tests of the closed form over intervals (`enclose.rs`) against the point solver and the
//! continuing solution: at a point each branch's enclosure holds one of the solver's branches,
//! and over a range the values and rates hold those sampled.

use super::Signs;
use crate::geometry::path::CartesianPath;
use crate::geometry::testing::Rng;
use crate::robot::ik::follow::testing::{irb, line_from, random_joints, seam, torch_frames, L1};
use crate::robot::ik::interval::Interval;
use crate::robot::Axes6;
use nalgebra::{Isometry3, Point3, UnitQuaternion};

/// Whether `x` lies in `a` up to full turns (deg).
fn holds(a: &Interval, x: f64) -> bool {
    let k = ((a.mid() - x) / 360.0).round();
    a.contains(x + 360.0 * k)
}

/// Random poses the IRB 1400 reaches (tool0 of random joints, `random_joints`): at the pose, the signs'
/// enclosures (where the branch exists) hold the solver's branches, each branch by one sign,
/// every enclosure narrow.
/// Fails with a step of the closed form transcribed wrong (a sign, an axis, a transpose).
#[test]
fn each_branch_at_a_pose_is_one_of_the_solvers() {
    let (robot, ik) = irb();
    let mut rng = Rng(53);
    let mut checked = 0;
    for _ in 0..200 {
        let joints = random_joints(&mut rng);
        let tool0 = robot.tool0(&joints);
        let Ok(branches) = ik.branches(&tool0, None) else {
            continue;
        };
        let path = CartesianPath::line(&tool0, &tool0).expect("a line");
        let form = ik.pose_form(&Isometry3::identity(), &path, &Isometry3::identity());
        let mut matched = vec![false; branches.len()];
        for signs in Signs::all() {
            // A stance whose elbow cannot reach the wrist centre has no branch.
            let Some(e) = ik.enclose(&form, Interval::point(0.5), signs) else {
                continue;
            };
            assert!(
                e.value_deg.iter().all(|v| v.width() < 1e-5),
                "{joints:?} {signs:?} {e:?}"
            );
            let hit = branches
                .iter()
                .position(|b| (0..6).all(|i| holds(&e.value_deg[i], b[i])))
                .unwrap_or_else(|| panic!("{joints:?} {signs:?}: {e:?} in none of {branches:?}"));
            matched[hit] = true;
        }
        assert!(matched.iter().all(|m| *m), "{joints:?}");
        checked += 1;
    }
    assert!(checked > 150, "{checked}");
}

/// Along torch-trunk's seam L1 -> L2 and along random arcs, over ranges of the progress of
/// several widths, the branch the path starts in holds the continuing solution's values
/// (up to full turns) and its central differences at sampled points (where it is defined: on
/// the widest ranges the overestimate may reach a step's singular case; never on the
/// narrowest). Fails with a rate rule wrong or the pose's form not the path's.
#[test]
fn over_a_range_the_values_and_rates_hold_the_continuing_solution() {
    let (robot, ik) = irb();
    let frames = torch_frames();
    let line = line_from(&robot, &frames, &L1, &seam(330.0, 630.0));
    let start = line.start();
    let turn = UnitQuaternion::from_euler_angles(0.3, -0.2, 0.4);
    let arc_end = Isometry3::from_parts(
        (seam(430.0, 630.0).translation.vector).into(),
        turn * start.rotation,
    );
    let via = Point3::from(seam(300.0, 480.0).translation.vector);
    let arc = CartesianPath::arc(&start, &via, &arc_end).expect("an arc");
    let from_cell = frames.cell_from_robot.inverse();
    let inv = frames.tframe.inverse();
    let mut rng = Rng(59);
    for path in [line, arc] {
        let form = ik.pose_form(&from_cell, &path, &inv);
        let signs = Signs::all()
            .into_iter()
            .find(|s| {
                ik.enclose(&form, Interval::point(0.0), *s)
                    .is_some_and(|e| (0..6).all(|i| holds(&e.value_deg[i], L1[i])))
            })
            .expect("L1 is on a branch");
        let at = |s: f64, q: &Axes6| {
            ik.continuing(&(from_cell * path.pose_at(s) * inv), q)
                .expect("reachable")
        };
        for width in [1e-4, 1e-2, 0.1] {
            let mut q = L1;
            let mut s0 = 0.0;
            while s0 + width <= 1.0 {
                let range = Interval::new(s0, s0 + width);
                let e = ik.enclose(&form, range, signs);
                assert!(e.is_some() || width > 1e-3, "{s0} {width}");
                for _ in 0..4 {
                    let Some(e) = e else {
                        break;
                    };
                    let s = rng.range(s0, s0 + width);
                    let h = 1e-7;
                    let (a, b, c) = (at(s - h, &q), at(s, &q), at(s + h, &q));
                    for i in 0..6 {
                        assert!(holds(&e.value_deg[i], b[i]), "{s} axis {i}");
                        let fd = (c[i] - a[i]) / (2.0 * h);
                        let slack = 1e-4 * (1.0 + fd.abs());
                        assert!(
                            e.rate_deg[i].lo() - slack <= fd && fd <= e.rate_deg[i].hi() + slack,
                            "{s} axis {i}: {fd} not in {:?}",
                            e.rate_deg[i]
                        );
                    }
                }
                q = at(s0 + width, &q);
                s0 += width;
            }
        }
    }
}
