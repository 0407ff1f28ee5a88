//! Every JSON the crate prints or writes: pretty, with a final newline, and a zero printed
//! without a sign (`0.0`, never `-0.0`: a computed zero such as the spin of a ball that left
//! without any is not negative in any sense a reader can use).

use serde::Serialize;
use serde_json::ser::{Formatter, PrettyFormatter};

use crate::error::{Error, Result};

/// `value` as pretty JSON with a final newline, each negative zero printed as `0.0`.
pub fn pretty(value: &impl Serialize) -> Result<String> {
    let mut bytes = Vec::new();
    let mut ser = serde_json::Serializer::with_formatter(&mut bytes, Unsigned(PrettyFormatter::new()));
    value.serialize(&mut ser).map_err(|e| Error::io("<json>", e))?;
    bytes.push(b'\n');
    String::from_utf8(bytes).map_err(|e| Error::io("<json>", e))
}

/// serde_json's pretty layout, with `-0.0` written as `0.0`.
struct Unsigned<'a>(PrettyFormatter<'a>);

/// The layout calls, handed to the pretty formatter.
macro_rules! delegate {
    ($($name:ident($($arg:ident: $ty:ty),*);)+) => {$(
        fn $name<W: ?Sized + std::io::Write>(&mut self, writer: &mut W $(, $arg: $ty)*) -> std::io::Result<()> {
            self.0.$name(writer $(, $arg)*)
        }
    )+};
}

impl Formatter for Unsigned<'_> {
    delegate! {
        begin_array();
        end_array();
        begin_array_value(first: bool);
        end_array_value();
        begin_object();
        end_object();
        begin_object_key(first: bool);
        begin_object_value();
        end_object_value();
    }

    fn write_f64<W: ?Sized + std::io::Write>(&mut self, writer: &mut W, value: f64) -> std::io::Result<()> {
        // (-0.0 == 0.0: adding 0.0 clears the sign of a zero and of nothing else)
        self.0.write_f64(writer, value + 0.0)
    }

    fn write_f32<W: ?Sized + std::io::Write>(&mut self, writer: &mut W, value: f32) -> std::io::Result<()> {
        self.0.write_f32(writer, value + 0.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_negative_zero_is_printed_as_zero_and_the_layout_is_serde_jsons() {
        let v = serde_json::json!({ "a": -0.0, "b": [-0.0_f64, -1.5, 2.0], "c": { "d": -0.0_f32, "e": "x" } });
        let ours = pretty(&v).unwrap();
        assert!(!ours.contains("-0"), "{ours}");
        let plain = serde_json::to_string_pretty(&v).unwrap().replace("-0.0", "0.0");
        assert_eq!(ours, format!("{plain}\n"));
        assert!(ours.contains("-1.5"));
        let nan_free: serde_json::Value = serde_json::from_str(&ours).unwrap();
        assert_eq!(nan_free["b"][1], -1.5);
    }
}
