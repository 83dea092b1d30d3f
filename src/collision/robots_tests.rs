//! Tests of the collision model on every shipped robot: the lumped arm and the flange's link
//! parts against parry3d's distances of the URDF's own cylinders, every link of every robot.

use super::tests::parry_distance;
use super::*;
use crate::geometry::testing::Rng;
use nalgebra::Point3;

fn bx(name: &str, min: [f64; 3], max: [f64; 3]) -> Obstacle {
    Obstacle::new(name, Aabb::new(Point3::from(min), Point3::from(max)))
}

/// Every shipped robot, every link: at random poses among random boxes, the model's smallest
/// distance (`clearance_at`, over the lumped arm's cylinders and the flange's parts) is at most
/// parry3d's distance of every URDF cylinder on its own link (`Robot::collision`, placed here
/// by the robot's forward kinematics), so a pose the model calls free keeps every link clear;
/// and where a URDF cylinder comes within the clearance of a box (not one the base stands on),
/// the model blocks the pose and names a link. Fails with link 5's ball a millimetre thinner
/// or the base's enclosure left out.
#[test]
fn every_shipped_robots_model_holds_every_link_of_its_urdf() {
    let mut rng = Rng(0x3_0030);
    let (mut measured, mut blocked) = (0usize, 0usize);
    for m in crate::robot::models::MODELS {
        let robot = Robot::shipped(m.name).expect("shipped");
        for _ in 0..6 {
            let boxes: Vec<Obstacle> = (0..6)
                .map(|k| {
                    let c = [
                        rng.range(-1500.0, 1500.0),
                        rng.range(-1500.0, 1500.0),
                        rng.range(100.0, 1800.0),
                    ];
                    let h = [
                        rng.range(20.0, 300.0),
                        rng.range(20.0, 300.0),
                        rng.range(20.0, 300.0),
                    ];
                    bx(
                        &format!("b{k}"),
                        [c[0] - h[0], c[1] - h[1], c[2] - h[2]],
                        [c[0] + h[0], c[1] + h[1], c[2] + h[2]],
                    )
                })
                .chain([bx(
                    "floor",
                    [-3000.0, -3000.0, -50.0],
                    [3000.0, 3000.0, 0.0],
                )])
                .collect();
            let pl = Placement {
                base_mm: [0.0, 0.0, 0.0],
                yaw_deg: rng.range(-180.0, 180.0),
            };
            let model = CollisionModel::new(&robot, pl, boxes.clone(), 10.0, None);
            let cell_from_robot = pl.cell_from_robot();
            for _ in 0..60 {
                let axes: [f64; 6] = std::array::from_fn(|i| {
                    let s = &robot.controller.axes[i];
                    rng.range(s.min_deg, s.max_deg)
                });
                if robot.check_range6(&axes).is_err() {
                    continue;
                }
                let links = robot.link_poses(&axes);
                let mut truth = f64::INFINITY;
                for own in &robot.collision {
                    let frame = match own.frame {
                        crate::robot::LinkFrame::Base => cell_from_robot,
                        crate::robot::LinkFrame::Child(k) => cell_from_robot * links[k],
                    };
                    let c = Cylinder {
                        a: frame * own.a,
                        b: frame * own.b,
                        radius: own.radius_mm,
                    };
                    for o in &boxes {
                        // The floor under the base and link 1 is what the robot stands on.
                        let stands = o.name == "floor"
                            && matches!(
                                own.frame,
                                crate::robot::LinkFrame::Base | crate::robot::LinkFrame::Child(0)
                            );
                        if !stands {
                            truth = truth.min(parry_distance(&c, &o.aabb));
                        }
                    }
                }
                let model_d = model.clearance_at(&axes);
                assert!(
                    model_d <= truth + 1e-6,
                    "{}: {axes:?}: the model measures {model_d} mm, a URDF cylinder {truth} mm",
                    m.name
                );
                measured += 1;
                if truth < 10.0 {
                    blocked += 1;
                    assert!(
                        !model.is_free(&axes),
                        "{}: {axes:?} free at {truth} mm",
                        m.name
                    );
                    assert!(
                        matches!(
                            model.why_blocked(&axes),
                            Some(Blocked::Contact {
                                part: Part::Link(_),
                                ..
                            })
                        ),
                        "{}: {axes:?}: {:?}",
                        m.name,
                        model.why_blocked(&axes)
                    );
                }
            }
        }
    }
    assert!(
        measured > 2000 && blocked > 200,
        "{measured} poses, {blocked} blocked"
    );
}
