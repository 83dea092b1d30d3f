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
//! only on the boxes and `L`); on torch-trunk about 94 k cubes of 50 mm, a ball's mask names
//! about a third of the nine boxes.

use crate::cell::Obstacle;
use crate::geometry::Point;

/// The least side of a cube, mm.
pub(super) const VOXEL_MM: f64 = 30.0;

/// The most cubes made: the side grows beyond [`VOXEL_MM`] for a region that would hold more.
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
    /// `None` without boxes or with more than [`MAX_BOXES`], or for a reach that is not a
    /// positive number.
    pub(super) fn new(obstacles: &[Obstacle], ball_mm: f64, reach_mm: f64) -> Option<NearBoxes> {
        if obstacles.is_empty() || obstacles.len() > MAX_BOXES || !(reach_mm > 0.0) {
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
        if !(lo.iter().chain(&hi).all(|v| v.is_finite())) {
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
            masks,
            all: ((1u32 << obstacles.len()) - 1) as u16,
            reach_mm,
            ball_mm,
        })
    }

    /// The boxes that may be within the reach of `p` (module doc): bit `b` for box `b`.
    #[inline]
    pub(super) fn mask(&self, p: &Point) -> u16 {
        let f = |k: usize| (p[k] - self.origin[k]) * self.inv_side;
        let (x, y, z) = (f(0), f(1), f(2));
        if x.is_nan() || y.is_nan() || z.is_nan() {
            return self.all;
        }
        let [dx, dy, dz] = self.dims;
        // Off the grid (below 0, or at or past the last cube): off the grown bounding box.
        if !(x >= 0.0 && y >= 0.0 && z >= 0.0) {
            return 0;
        }
        let (x, y, z) = (x as usize, y as usize, z as usize);
        if x >= dx || y >= dy || z >= dz {
            return 0;
        }
        self.masks
            .get((z * dy + y) * dx + x)
            .copied()
            .unwrap_or(self.all)
    }
}
