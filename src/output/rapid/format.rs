//! Fixed-decimal number formatting for RAPID text.

/// Formats `value` with exactly `decimals` digits after the decimal point.
///
/// Guarantees, for finite input:
/// - plain positional notation: never an exponent (`1e300` prints all digits);
/// - exactly `decimals` fractional digits (no decimal point when `decimals == 0`);
/// - never a negative zero: any value that rounds to zero at the requested
///   precision (including `-0.0` and e.g. `-0.0004` at 3 decimals) prints as
///   `0`, `0.0`, `0.000`, ... without a sign;
/// - rounding is done on the exact binary value of `value`, and exact ties
///   (only possible for values exactly representable in binary, such as
///   `0.125` or `2.5`) go to the even digit: `format_fixed(0.125, 2) == "0.12"`,
///   `format_fixed(2.5, 0) == "2"`. A decimal literal like `1.0005` is
///   stored slightly below the tie and rounds down to `"1.000"`.
///
/// Non-finite input is not a number RAPID can read; it is printed as Rust
/// prints it (`NaN`, `inf`, `-inf`) so this function never panics.
/// [`render`](super::render) refuses non-finite values before formatting.
pub fn format_fixed(value: f64, decimals: usize) -> String {
    let text = format!("{value:.decimals$}");
    match text.strip_prefix('-') {
        Some(rest) if rest.bytes().all(|b| b == b'0' || b == b'.') => rest.to_string(),
        _ => text,
    }
}

#[cfg(test)]
mod tests {
    use super::format_fixed;

    #[test]
    fn format_fixed_negative_rounding_to_zero_has_no_sign() {
        assert_eq!(format_fixed(-0.0004, 3), "0.000");
        assert_eq!(format_fixed(-0.0004999, 3), "0.000");
        assert_eq!(format_fixed(-0.04, 1), "0.0");
        assert_eq!(format_fixed(-0.4, 0), "0");
    }

    #[test]
    fn format_fixed_negative_zero() {
        assert_eq!(format_fixed(-0.0, 3), "0.000");
        assert_eq!(format_fixed(-0.0, 0), "0");
        assert_eq!(format_fixed(0.0, 3), "0.000");
    }

    #[test]
    fn format_fixed_keeps_sign_of_nonzero_results() {
        assert_eq!(format_fixed(-0.0006, 3), "-0.001");
        assert_eq!(format_fixed(-12.3456, 3), "-12.346");
        assert_eq!(format_fixed(-0.6, 0), "-1");
        assert_eq!(format_fixed(-100.0, 1), "-100.0");
    }

    #[test]
    fn format_fixed_exact_decimals() {
        assert_eq!(format_fixed(1.0, 3), "1.000");
        assert_eq!(format_fixed(90.0, 3), "90.000");
        assert_eq!(format_fixed(1.23456, 2), "1.23");
        assert_eq!(format_fixed(7.0, 0), "7");
    }

    #[test]
    fn format_fixed_large_values_have_no_exponent() {
        let big = format_fixed(1e300, 3);
        assert_eq!(big.parse::<f64>().unwrap(), 1e300);
        assert!(big[..301].bytes().all(|b| b.is_ascii_digit()), "{big}");
        assert!(big.ends_with(".000"));
        assert!(!big.contains(['e', 'E']));
        assert_eq!(big.len(), 301 + 4);
        assert_eq!(format_fixed(-123456789.0, 3), "-123456789.000");
        assert!(!format_fixed(f64::MAX, 3).contains(['e', 'E']));
        assert!(!format_fixed(1e-300, 3).contains(['e', 'E']));
        assert_eq!(format_fixed(1e-300, 3), "0.000");
        assert_eq!(format_fixed(-1e-300, 3), "0.000");
    }

    #[test]
    fn format_fixed_halfway_cases_round_half_to_even_on_exact_binary() {
        // Exactly representable ties: half to even.
        assert_eq!(format_fixed(0.125, 2), "0.12");
        assert_eq!(format_fixed(0.375, 2), "0.38");
        assert_eq!(format_fixed(2.5, 0), "2");
        assert_eq!(format_fixed(3.5, 0), "4");
        assert_eq!(format_fixed(-2.5, 0), "-2");
        assert_eq!(format_fixed(-0.5, 0), "0");
        // Decimal "ties" that are not exact in binary round by the true value.
        assert_eq!(format_fixed(1.0005, 3), "1.000"); // stored as 1.000499999...
        assert_eq!(format_fixed(0.0005, 3), "0.001"); // stored as 0.000500000...01
        assert_eq!(format_fixed(-0.0005, 3), "-0.001");
    }

    #[test]
    fn format_fixed_non_finite_does_not_panic() {
        assert_eq!(format_fixed(f64::NAN, 3), "NaN");
        assert_eq!(format_fixed(f64::INFINITY, 3), "inf");
        assert_eq!(format_fixed(f64::NEG_INFINITY, 3), "-inf");
    }
}
