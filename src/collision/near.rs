//! Which boxes a tool ball can come near, by voxel (beyond the paper): the balls' pass of a leg's
//! tool look (`CollisionModel::ball_pass`) measures each ball against the boxes its voxel names
//! instead of against every box.
//!
//! The boxes' bounding box, grown by the reach `L` and 1 mm, is cut into cubes of side `v`
//! (at least [`VOXEL_MM`], more where the region would hold over [`MAX_VOXELS`] of them). A cube
//! names box `b` (bit `b` of its mask) unless the distance from the cube's centre to `b`, less
//! the cube's half diagonal and 1e-3 mm (for the rounding of the cube's index), exceeds `L`:
//! every point in the cube is then farther than `L` from `b` (the distance to a box is
//! 1-Lipschitz). A point off the grown bounding box is farther than `L` from every box (mask 0).
//! So a box a point's mask leaves out is farther than `L` from the point: a ball of radius `r`
//! about it keeps more than `L - r` from that box, which is all the look needs to know of it
//! when `L - r` exceeds the clearance and the margin it can use (module doc of `plan::leg`).
//!
//! Made on the first look of a model with at most [`MAX_BOXES`] boxes, once (the masks depend
//! only on the boxes and `L`); on torch-trunk a few hundred thousand cubes of 30 mm, under a
//! megabyte, made in a small part of a run. 30 mm cubes cost a run fewer instructions than
//! 50 mm ones there (`benches/README.md`).

use crate::cell::Obstacle;
use crate::geometry::Point;

/// The least side of a cube, mm.
pub(super) const VOXEL_MM: f64 = 30.0;

/// The cubes a region is cut into at most, about: the side grows beyond [`VOXEL_MM`] for a
/// region that would hold more; a region whose sides round up to over twice as many (a long
/// thin one) gets no masks.
pub(super) const MAX_VOXELS: usize = 1_000_000;

/// The most boxes a mask can name (one bit each); a model with more measures every box.
pub(super) const MAX_BOXES: usize = 16;

/// The masks by cube (module doc).
#[derive(Clone, Debug)]
pub(super) struct NearBoxes {
    /// The grown bounding box's lower corner, mm.
    origin: [f64; 3],
    /// `1 / v`, per mm.
    inv_side: f64,
    /// Cubes along x, y, z.
    dims: [usize; 3],
    /// The same as numbers.
    dims_f: [f64; 3],
    /// Per cube (x fastest, then y, then z): bit `b` set where box `b` may be within `L`.
    masks: Vec<u16>,
    /// Every box's bit (the mask of a point that is not a number).
    all: u16,
    /// `L`, mm.
    pub reach_mm: f64,
    /// The largest radius of the balls measured with these masks, mm.
    pub ball_mm: f64,
}

impl NearBoxes {
    /// The masks of `obstacles` for reach `reach_mm`, for balls of radius up to `ball_mm`;
    /// `None` without boxes or with more than [`MAX_BOXES`], for a reach that is not a
    /// positive number, for bounds that are not finite, or for a region of over twice
    /// [`MAX_VOXELS`] cubes.
    pub(super) fn new(obstacles: &[Obstacle], ball_mm: f64, reach_mm: f64) -> Option<NearBoxes> {
        if obstacles.is_empty()
            || obstacles.len() > MAX_BOXES
            || reach_mm.is_nan()
            || reach_mm <= 0.0
        {
            return None;
        }
        let grow = reach_mm + 1.0;
        let lo: [f64; 3] = std::array::from_fn(|k| {
            obstacles
                .iter()
                .map(|o| o.aabb.min[k])
                .fold(f64::INFINITY, f64::min)
                - grow
        });
        let hi: [f64; 3] = std::array::from_fn(|k| {
            obstacles
                .iter()
                .map(|o| o.aabb.max[k])
                .fold(f64::NEG_INFINITY, f64::max)
                + grow
        });
        if !lo.iter().chain(&hi).all(|v| v.is_finite()) {
            return None;
        }
        let volume: f64 = (0..3).map(|k| hi[k] - lo[k]).product();
        let side = VOXEL_MM.max((volume / MAX_VOXELS as f64).cbrt() * 1.01);
        let dims: [usize; 3] =
            std::array::from_fn(|k| (((hi[k] - lo[k]) / side).ceil() as usize).max(1));
        if dims.iter().product::<usize>() > 2 * MAX_VOXELS {
            return None;
        }
        let half_diagonal = 0.5 * side * 3f64.sqrt();
        // Per box and axis, the squared excess of each cube's centre coordinate over the box's
        // range: the squared distance is their sum (the rounding of the squares, about 1e-12
        // mm, is far inside the 1e-3 mm of the test).
        let centre = |k: usize, i: usize| lo[k] + (i as f64 + 0.5) * side;
        let sq_excess: Vec<[Vec<f64>; 3]> = obstacles
            .iter()
            .map(|o| {
                std::array::from_fn(|k| {
                    (0..dims[k])
                        .map(|i| {
                            let x = centre(k, i);
                            let e = (o.aabb.min[k] - x).max(x - o.aabb.max[k]).max(0.0);
                            e * e
                        })
                        .collect()
                })
            })
            .collect();
        let within = (reach_mm + half_diagonal + 1e-3).powi(2);
        let mut masks = vec![0u16; dims.iter().product()];
        for (b, [ex, ey, ez]) in sq_excess.iter().enumerate() {
            for (z, ez) in ez.iter().enumerate() {
                for (y, ey) in ey.iter().enumerate() {
                    // The room left along x in this row of cubes; none: the row stays clear.
                    let room = within - ey - ez;
                    if room < 0.0 {
                        continue;
                    }
                    let row = (z * dims[1] + y) * dims[0];
                    for (m, ex) in masks[row..row + dims[0]].iter_mut().zip(ex) {
                        if *ex <= room {
                            *m |= 1 << b;
                        }
                    }
                }
            }
        }
        Some(NearBoxes {
            origin: lo,
            inv_side: 1.0 / side,
            dims,
            dims_f: dims.map(|d| d as f64),
            masks,
            all: ((1u32 << obstacles.len()) - 1) as u16,
            reach_mm,
            ball_mm,
        })
    }

    /// The boxes that may be within the reach of `p` (module doc): bit `b` for box `b`.
    #[inline]
    pub(super) fn mask(&self, p: &Point) -> u16 {
        let [x, y, z] = [0, 1, 2].map(|k| (p[k] - self.origin[k]) * self.inv_side);
        let [dx, dy, dz] = self.dims_f;
        // On the grid: the cube's mask. The index is `x - 1/2` rounded to the nearest integer
        // by adding `1.5 2^52` (the integer in the low bits; at most `2 MAX_VOXELS`): `floor(x)`
        // except within a few ulps of a cube's face, where either cube's mask holds (the masks'
        // test has 1e-3 mm of room).
        if x >= 0.0 && y >= 0.0 && z >= 0.0 && x < dx && y < dy && z < dz {
            const ROUND: f64 = 6_755_399_441_055_744.0;
            let index = |v: f64| ((v - 0.5) + ROUND).to_bits() as u32 as usize;
            let (x, y, z) = (index(x), index(y), index(z));
            let [nx, ny, _] = self.dims;
            return self
                .masks
                .get((z * ny + y) * nx + x)
                .copied()
                .unwrap_or(self.all);
        }
        // Not a number: every box; else off the grid (below 0, or at or past the last cube),
        // so off the grown bounding box: none.
        if x.is_nan() || y.is_nan() || z.is_nan() {
            self.all
        } else {
            0
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::testing::Rng;
    use crate::geometry::{distance_point_aabb, Aabb};

    fn random_boxes(rng: &mut Rng, n: usize) -> Vec<Obstacle> {
        (0..n)
            .map(|k| {
                let c = [0, 1, 2].map(|_| rng.range(-1000.0, 1000.0));
                let h = [0, 1, 2].map(|_| rng.range(1.0, 400.0));
                Obstacle {
                    name: format!("b{k}"),
                    aabb: Aabb::new(
                        Point::new(c[0] - h[0], c[1] - h[1], c[2] - h[2]),
                        Point::new(c[0] + h[0], c[1] + h[1], c[2] + h[2]),
                    ),
                    loc: crate::cell::Loc { line: 1, column: 1 },
                }
            })
            .collect()
    }

    /// Every box a point's mask leaves out is farther than the reach from the point, for random
    /// boxes, reaches and points (in the boxes' region, near its border and far off it), and
    /// the masks do leave boxes out (else the test would hold for masks of every box).
    /// Points are drawn near the cubes' corners too, where a mask made from the cube's centre
    /// without its half diagonal would name too few boxes.
    #[test]
    fn a_box_left_out_is_farther_than_the_reach() {
        let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
        let (mut left_out, mut named) = (0usize, 0usize);
        for case in 0..40 {
            let boxes = random_boxes(&mut rng, 1 + case % MAX_BOXES);
            let reach = rng.range(5.0, 400.0);
            let near = NearBoxes::new(&boxes, 50.0, reach).expect("masks");
            let side = 1.0 / near.inv_side;
            for _ in 0..3000 {
                let p = if rng.range(0.0, 1.0) < 0.5 {
                    Point::new(
                        rng.range(-2000.0, 2000.0),
                        rng.range(-2000.0, 2000.0),
                        rng.range(-2000.0, 2000.0),
                    )
                } else {
                    // Near a corner of a cube.
                    let i = [0, 1, 2].map(|k| (rng.range(0.0, near.dims[k] as f64)).floor());
                    let e = [0, 1, 2].map(|_| rng.range(-1e-6, 1e-6) * side);
                    Point::new(
                        near.origin[0] + i[0] * side + e[0],
                        near.origin[1] + i[1] * side + e[1],
                        near.origin[2] + i[2] * side + e[2],
                    )
                };
                let mask = near.mask(&p);
                for (b, o) in boxes.iter().enumerate() {
                    if mask >> b & 1 == 0 {
                        left_out += 1;
                        let d = distance_point_aabb(&p, &o.aabb);
                        assert!(d > reach, "case {case}: box {b} at {d} <= {reach} left out");
                    } else {
                        named += 1;
                    }
                }
            }
            // Far off every box: no box; not a number: every box.
            assert_eq!(near.mask(&Point::new(1e7, 0.0, 0.0)), 0);
            assert_eq!(near.mask(&Point::new(-1e7, -1e7, -1e7)), 0);
            assert_eq!(near.mask(&Point::new(f64::NAN, 0.0, 0.0)), near.all);
        }
        assert!(
            left_out > 10 * named / 100,
            "{left_out} left out, {named} named"
        );
        assert!(named > 0);
    }

    /// No masks without boxes, with more boxes than a mask holds, or without a reach.
    #[test]
    fn no_masks_where_they_cannot_hold() {
        let mut rng = Rng(7);
        assert!(NearBoxes::new(&[], 10.0, 100.0).is_none());
        assert!(NearBoxes::new(&random_boxes(&mut rng, MAX_BOXES + 1), 10.0, 100.0).is_none());
        assert!(NearBoxes::new(&random_boxes(&mut rng, 3), 10.0, 0.0).is_none());
        assert!(NearBoxes::new(&random_boxes(&mut rng, 3), 10.0, f64::NAN).is_none());
        assert!(NearBoxes::new(&random_boxes(&mut rng, MAX_BOXES), 10.0, 100.0).is_some());
    }
}
