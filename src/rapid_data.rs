//! RAPID's predefined motion data: the `speeddata` (`v5` .. `v7000`, `vmax`) and `zonedata`
//! (`fine`, `z0` .. `z200`) a cell may name, as typed tables.
//!
//! A leaf: it reads no files and depends on nothing in the crate. The cell loader uses it to
//! know a speed or zone name, the time estimate to read `v_tcp` / `v_ori`, the zone
//! certification to know whether a zone is a stop point.
//!
//! Source: ABB, *Technical reference manual - RAPID Instructions, Functions and Data types*,
//! entries `speeddata` and `zonedata` ("Predefined data"); the values were checked against
//! several independent public listings. `docs/rapid.md` gives the same tables with their
//! sources and what each field means; a unit test below parses that page and fails when the two
//! disagree, so change both together.
//!
//! Names are matched without regard to case, as RAPID does (`V100` is `v100`).

/// A RAPID `speeddata` value: `[v_tcp, v_ori, v_leax, v_reax]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpeedData {
    /// TCP speed (mm/s).
    pub v_tcp_mm_s: f64,
    /// Reorientation speed of the tool about the TCP (deg/s).
    pub v_ori_deg_s: f64,
    /// Speed of linear external axes (mm/s).
    pub v_leax_mm_s: f64,
    /// Speed of rotating external axes (deg/s).
    pub v_reax_deg_s: f64,
}

/// A RAPID `zonedata` value:
/// `[finep, pzone_tcp, pzone_ori, pzone_eax, zone_ori, zone_leax, zone_reax]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ZoneData {
    /// TRUE: a stop point (the robot comes to rest at the target); FALSE: a fly-by point.
    pub finep: bool,
    /// Radius of the TCP zone (mm).
    pub pzone_tcp_mm: f64,
    /// Zone radius for tool reorientation, as a TCP distance (mm).
    pub pzone_ori_mm: f64,
    /// Zone radius for external axes, as a TCP distance (mm).
    pub pzone_eax_mm: f64,
    /// Zone size for tool reorientation (deg).
    pub zone_ori_deg: f64,
    /// Zone size for linear external axes (mm).
    pub zone_leax_mm: f64,
    /// Zone size for rotating external axes (deg).
    pub zone_reax_deg: f64,
}

/// `v_tcp` (mm/s) the table gives `vmax`: the figure public RAPID reimplementations use.
///
/// On a controller `vmax`'s `v_tcp` is the robot type's maximum TCP speed (what RAPID's
/// `MaxRobSpeed()` returns); for the IRB 1400 (about 2.1 m/s) 5000 mm/s never binds, so the axes
/// limit every move, which is what `vmax` means. Use [`vmax_for`] where the robot's figure is
/// known. See `docs/rapid.md`, "Predefined speeddata".
pub const VMAX_GENERIC_V_TCP_MM_S: f64 = 5000.0;

/// The `v_ori`, `v_leax`, `v_reax` every predefined speeddata shares.
const fn speed(v_tcp_mm_s: f64) -> SpeedData {
    SpeedData {
        v_tcp_mm_s,
        v_ori_deg_s: 500.0,
        v_leax_mm_s: 5000.0,
        v_reax_deg_s: 1000.0,
    }
}

/// A fly-by zone of the predefined pattern.
const fn fly_by(tcp: f64, ori: f64, ori_deg: f64) -> ZoneData {
    ZoneData {
        finep: false,
        pzone_tcp_mm: tcp,
        pzone_ori_mm: ori,
        pzone_eax_mm: ori,
        zone_ori_deg: ori_deg,
        zone_leax_mm: ori,
        zone_reax_deg: ori_deg,
    }
}

/// The predefined speeddata, in the order of the RAPID reference (and of `docs/rapid.md`).
pub const PREDEFINED_SPEEDS: &[(&str, SpeedData)] = &[
    ("v5", speed(5.0)),
    ("v10", speed(10.0)),
    ("v20", speed(20.0)),
    ("v30", speed(30.0)),
    ("v40", speed(40.0)),
    ("v50", speed(50.0)),
    ("v60", speed(60.0)),
    ("v80", speed(80.0)),
    ("v100", speed(100.0)),
    ("v150", speed(150.0)),
    ("v200", speed(200.0)),
    ("v300", speed(300.0)),
    ("v400", speed(400.0)),
    ("v500", speed(500.0)),
    ("v600", speed(600.0)),
    ("v800", speed(800.0)),
    ("v1000", speed(1000.0)),
    ("v1500", speed(1500.0)),
    ("v2000", speed(2000.0)),
    ("v2500", speed(2500.0)),
    ("v3000", speed(3000.0)),
    ("v4000", speed(4000.0)),
    ("v5000", speed(5000.0)),
    ("v6000", speed(6000.0)),
    ("v7000", speed(7000.0)),
    ("vmax", speed(VMAX_GENERIC_V_TCP_MM_S)),
];

/// The predefined zonedata, in the order of the RAPID reference (and of `docs/rapid.md`).
pub const PREDEFINED_ZONES: &[(&str, ZoneData)] = &[
    (
        "fine",
        ZoneData {
            finep: true,
            pzone_tcp_mm: 0.0,
            pzone_ori_mm: 0.0,
            pzone_eax_mm: 0.0,
            zone_ori_deg: 0.0,
            zone_leax_mm: 0.0,
            zone_reax_deg: 0.0,
        },
    ),
    ("z0", fly_by(0.3, 0.3, 0.03)),
    ("z1", fly_by(1.0, 1.0, 0.1)),
    ("z5", fly_by(5.0, 8.0, 0.8)),
    ("z10", fly_by(10.0, 15.0, 1.5)),
    ("z15", fly_by(15.0, 23.0, 2.3)),
    ("z20", fly_by(20.0, 30.0, 3.0)),
    ("z30", fly_by(30.0, 45.0, 4.5)),
    ("z40", fly_by(40.0, 60.0, 6.0)),
    ("z50", fly_by(50.0, 75.0, 7.5)),
    ("z60", fly_by(60.0, 90.0, 9.0)),
    ("z80", fly_by(80.0, 120.0, 12.0)),
    ("z100", fly_by(100.0, 150.0, 15.0)),
    ("z150", fly_by(150.0, 225.0, 23.0)),
    ("z200", fly_by(200.0, 300.0, 30.0)),
];

/// The predefined speeddata called `name` (any case), or `None` when RAPID predefines no
/// speeddata of that name.
pub fn predefined_speed(name: &str) -> Option<SpeedData> {
    PREDEFINED_SPEEDS
        .iter()
        .find(|(n, _)| n.eq_ignore_ascii_case(name))
        .map(|&(_, s)| s)
}

/// The predefined zonedata called `name` (any case), or `None` when RAPID predefines no
/// zonedata of that name.
pub fn predefined_zone(name: &str) -> Option<ZoneData> {
    PREDEFINED_ZONES
        .iter()
        .find(|(n, _)| n.eq_ignore_ascii_case(name))
        .map(|&(_, z)| z)
}

/// `vmax` for a robot whose maximum TCP speed (`MaxRobSpeed()`, mm/s) is known: the table's
/// `vmax` with that `v_tcp`.
pub fn vmax_for(max_tcp_mm_s: f64) -> SpeedData {
    speed(max_tcp_mm_s)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::HashSet;

    /// `docs/rapid.md`, compiled in so the test needs no file access at run time.
    const RAPID_MD: &str = include_str!("../docs/rapid.md");

    /// The number in a `v<digits>` / `z<digits>` name.
    fn number_in(name: &str, prefix: char) -> Option<f64> {
        let digits = name.strip_prefix(prefix)?;
        if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
            return None;
        }
        digits.parse().ok()
    }

    fn assert_unique(names: impl Iterator<Item = &'static str>) {
        let mut seen = HashSet::new();
        for n in names {
            assert!(
                seen.insert(n.to_ascii_lowercase()),
                "name {n} appears twice"
            );
        }
    }

    #[test]
    fn names_are_unique_regardless_of_case() {
        assert_unique(PREDEFINED_SPEEDS.iter().map(|(n, _)| *n));
        assert_unique(PREDEFINED_ZONES.iter().map(|(n, _)| *n));
        let speeds: HashSet<_> = PREDEFINED_SPEEDS.iter().map(|(n, _)| *n).collect();
        assert!(PREDEFINED_ZONES.iter().all(|(n, _)| !speeds.contains(n)));
    }

    #[test]
    fn speed_table_has_the_v_series_and_vmax() {
        assert_eq!(PREDEFINED_SPEEDS.len(), 26);
        let v_series: Vec<_> = PREDEFINED_SPEEDS
            .iter()
            .filter_map(|(n, s)| number_in(n, 'v').map(|v| (v, *s)))
            .collect();
        assert_eq!(v_series.len(), 25, "v5 .. v7000");
        assert_eq!(v_series.first().map(|p| p.0), Some(5.0));
        assert_eq!(v_series.last().map(|p| p.0), Some(7000.0));
        for (v, s) in &v_series {
            assert_eq!(s.v_tcp_mm_s, *v, "v{v}: v_tcp is the number in the name");
        }
        for pair in v_series.windows(2) {
            assert!(
                pair[0].1.v_tcp_mm_s < pair[1].1.v_tcp_mm_s,
                "v_tcp strictly increasing along the v-series"
            );
        }
        for (name, s) in PREDEFINED_SPEEDS {
            assert_eq!(
                (s.v_ori_deg_s, s.v_leax_mm_s, s.v_reax_deg_s),
                (500.0, 5000.0, 1000.0),
                "{name}: the shared v_ori, v_leax, v_reax"
            );
        }
        let vmax = predefined_speed("vmax").expect("vmax is predefined");
        assert_eq!(vmax.v_tcp_mm_s, VMAX_GENERIC_V_TCP_MM_S);
    }

    #[test]
    fn zones_grow_and_follow_the_predefined_pattern() {
        assert_eq!(PREDEFINED_ZONES.len(), 15);
        let fine = predefined_zone("fine").expect("fine is predefined");
        assert!(fine.finep, "fine is a stop point");
        assert_eq!(
            [
                fine.pzone_tcp_mm,
                fine.pzone_ori_mm,
                fine.pzone_eax_mm,
                fine.zone_ori_deg,
                fine.zone_leax_mm,
                fine.zone_reax_deg
            ],
            [0.0; 6]
        );
        let fly: Vec<_> = PREDEFINED_ZONES
            .iter()
            .filter(|(n, _)| *n != "fine")
            .collect();
        assert_eq!(fly.len(), 14);
        for (name, z) in &fly {
            let n = number_in(name, 'z').expect("every other zone is z<number>");
            assert!(!z.finep, "{name} is a fly-by point");
            // z0 is not a zero zone: its TCP radius is 0.3 mm.
            let tcp = if n == 0.0 { 0.3 } else { n };
            assert_eq!(z.pzone_tcp_mm, tcp, "{name}: pzone_tcp from the name");
            assert!(
                z.pzone_ori_mm >= z.pzone_tcp_mm,
                "{name}: pzone_ori >= pzone_tcp"
            );
            assert_eq!(z.pzone_eax_mm, z.pzone_ori_mm, "{name}");
            assert_eq!(z.zone_leax_mm, z.pzone_ori_mm, "{name}");
            assert_eq!(z.zone_reax_deg, z.zone_ori_deg, "{name}");
            // From z5 on the extended zones are 1.5 pzone_tcp and the angles a tenth of them,
            // each rounded (z15: 22.5 -> 23; z150: 22.5 deg -> 23).
            if n >= 5.0 {
                assert!((z.pzone_ori_mm - 1.5 * n).abs() <= 0.5, "{name}: pzone_ori");
            }
            assert!(
                (z.zone_ori_deg - z.pzone_ori_mm / 10.0).abs() <= 0.5,
                "{name}: zone_ori"
            );
        }
        for pair in fly.windows(2) {
            let (a, b) = (pair[0].1, pair[1].1);
            assert!(a.pzone_tcp_mm < b.pzone_tcp_mm, "pzone_tcp increasing");
            assert!(a.pzone_ori_mm < b.pzone_ori_mm, "pzone_ori increasing");
            assert!(a.zone_ori_deg < b.zone_ori_deg, "zone_ori increasing");
        }
    }

    #[test]
    fn lookup_ignores_case_and_refuses_unknown_names() {
        assert_eq!(predefined_speed("V100"), predefined_speed("v100"));
        assert_eq!(predefined_speed("v100").map(|s| s.v_tcp_mm_s), Some(100.0));
        assert_eq!(predefined_zone("FINE").map(|z| z.finep), Some(true));
        assert_eq!(predefined_zone("Z50").map(|z| z.pzone_tcp_mm), Some(50.0));
        for unknown in ["", "v", "v0", "v7", "v123", "v8000", "vmin", "fine", "z50"] {
            assert_eq!(predefined_speed(unknown), None, "{unknown:?}");
        }
        for unknown in ["", "z", "z2", "z25", "z250", "zfine", "v100", " z10"] {
            assert_eq!(predefined_zone(unknown), None, "{unknown:?}");
        }
    }

    #[test]
    fn vmax_for_keeps_the_shared_fields() {
        let s = vmax_for(2100.0);
        assert_eq!(s.v_tcp_mm_s, 2100.0);
        assert_eq!(
            (s.v_ori_deg_s, s.v_leax_mm_s, s.v_reax_deg_s),
            (500.0, 5000.0, 1000.0)
        );
    }

    /// The rows of the markdown table whose header row starts with `header_start`: each row's
    /// cells, trimmed, backticks removed, each cell cut at its first space (so a note after the
    /// value, "5000 (robot-dependent, see below)", is dropped).
    fn markdown_table(doc: &str, header_start: &str) -> Vec<Vec<String>> {
        let mut lines = doc.lines();
        let found = lines
            .by_ref()
            .any(|l| l.trim_start().starts_with(header_start));
        assert!(
            found,
            "docs/rapid.md has no table starting {header_start:?}"
        );
        let separator = lines.next().unwrap_or_default();
        assert!(
            separator.trim_start().starts_with("|---"),
            "table {header_start:?}: separator row expected, found {separator:?}"
        );
        lines
            .take_while(|l| l.trim_start().starts_with('|'))
            .map(|l| {
                l.trim()
                    .trim_matches('|')
                    .split('|')
                    .map(|c| {
                        let c = c.trim().replace('`', "");
                        c.split(' ').next().unwrap_or_default().to_string()
                    })
                    .collect()
            })
            .collect()
    }

    fn num(cell: &str, what: &str) -> f64 {
        cell.parse()
            .unwrap_or_else(|_| panic!("docs/rapid.md, {what}: {cell:?} is not a number"))
    }

    #[test]
    fn docs_speed_table_matches() {
        let rows = markdown_table(RAPID_MD, "| name | v_tcp (mm/s) |");
        let names: Vec<_> = rows.iter().map(|r| r[0].as_str()).collect();
        let ours: Vec<_> = PREDEFINED_SPEEDS.iter().map(|(n, _)| *n).collect();
        assert_eq!(names, ours, "same names in the same order");
        for (row, (name, s)) in rows.iter().zip(PREDEFINED_SPEEDS) {
            assert_eq!(row.len(), 5, "{name}: five columns");
            let doc = SpeedData {
                v_tcp_mm_s: num(&row[1], name),
                v_ori_deg_s: num(&row[2], name),
                v_leax_mm_s: num(&row[3], name),
                v_reax_deg_s: num(&row[4], name),
            };
            assert_eq!(&doc, s, "{name}: docs/rapid.md against src/rapid_data.rs");
        }
    }

    #[test]
    fn docs_zone_table_matches() {
        let rows = markdown_table(RAPID_MD, "| name | finep |");
        let names: Vec<_> = rows.iter().map(|r| r[0].as_str()).collect();
        let ours: Vec<_> = PREDEFINED_ZONES.iter().map(|(n, _)| *n).collect();
        assert_eq!(names, ours, "same names in the same order");
        for (row, (name, z)) in rows.iter().zip(PREDEFINED_ZONES) {
            assert_eq!(row.len(), 8, "{name}: eight columns");
            let finep = match row[1].as_str() {
                "TRUE" => true,
                "FALSE" => false,
                other => panic!("docs/rapid.md, {name}: finep {other:?} is not TRUE/FALSE"),
            };
            let doc = ZoneData {
                finep,
                pzone_tcp_mm: num(&row[2], name),
                pzone_ori_mm: num(&row[3], name),
                pzone_eax_mm: num(&row[4], name),
                zone_ori_deg: num(&row[5], name),
                zone_leax_mm: num(&row[6], name),
                zone_reax_deg: num(&row[7], name),
            };
            assert_eq!(&doc, z, "{name}: docs/rapid.md against src/rapid_data.rs");
        }
    }
}
