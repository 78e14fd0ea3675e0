//! How numbers are written into the docs' tables.

/// Three significant digits, trailing zeros dropped, as C's `%.3g` (a ratio: 0.0955, 1.05, 43.3).
pub fn g3(x: f64) -> String {
    g(x, 3)
}

/// `digits` significant digits, trailing zeros dropped, as C's `%.{digits}g` but with a plain
/// exponent (`1.6e-5`).
pub fn g(x: f64, digits: usize) -> String {
    if !x.is_finite() {
        return x.to_string();
    }
    if x == 0.0 {
        return "0".into();
    }
    let digits = digits.max(1);
    // The decimal exponent after rounding to `digits` digits (9.996 → 1.00e1 at 3 digits).
    let rounded = format!("{:.*e}", digits - 1, x);
    let (mantissa, exp) = rounded.split_once('e').unwrap_or((&rounded, "0"));
    let exp: i32 = exp.parse().unwrap_or(0);
    if exp < -4 || exp >= digits as i32 {
        return format!("{}e{exp}", trim_zeros(mantissa));
    }
    let decimals = (digits as i32 - 1 - exp).max(0) as usize;
    trim_zeros(&format!("{x:.decimals$}"))
}

fn trim_zeros(s: &str) -> String {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s.to_string()
    }
}

/// A duration given in ns, in the unit that keeps it below 10⁴: `42.6 ns`, `3426 ns`, `191.6 µs`,
/// `4.23 ms` (three significant digits, or the integer part when it has more).
pub fn time_ns(ns: f64) -> String {
    let (v, unit) = if ns < 1e4 {
        (ns, "ns")
    } else if ns < 1e7 {
        (ns / 1e3, "µs")
    } else {
        (ns / 1e6, "ms")
    };
    let digits = if v >= 100.0 {
        0
    } else if v >= 10.0 {
        1
    } else {
        2
    };
    format!("{v:.digits$} {unit}")
}

/// A duration given in seconds, in µs with one decimal (the trade tables' cost column).
pub fn micros(seconds: f64) -> String {
    format!("{:.1} µs", seconds * 1e6)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn three_significant_digits_like_printf_g() {
        assert_eq!(g3(0.509), "0.509");
        assert_eq!(g3(0.0998), "0.0998");
        assert_eq!(g3(0.00955), "0.00955");
        assert_eq!(g3(1.0), "1");
        assert_eq!(g3(43.33), "43.3");
        assert_eq!(g3(9.996), "10");
        assert_eq!(g3(2.0), "2");
        assert_eq!(g3(1234.0), "1.23e3");
        assert_eq!(g3(0.00001234), "1.23e-5");
        assert_eq!(g(0.0124955, 6), "0.0124955");
        assert_eq!(g(0.0003125, 6), "0.0003125");
        assert_eq!(g(1.6e-5, 6), "1.6e-5");
        assert_eq!(g(10.0, 6), "10");
    }

    #[test]
    fn times_keep_three_digits_in_a_readable_unit() {
        assert_eq!(time_ns(9.43), "9.43 ns");
        assert_eq!(time_ns(42.64), "42.6 ns");
        assert_eq!(time_ns(3426.4), "3426 ns");
        assert_eq!(time_ns(191_600.0), "192 µs");
        assert_eq!(time_ns(39_600.0), "39.6 µs");
        assert_eq!(time_ns(4_230_000.0), "4230 µs");
        assert_eq!(time_ns(58_200_000.0), "58.2 ms");
        assert_eq!(micros(1.6e-6), "1.6 µs");
    }
}
