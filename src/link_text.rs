//! How a value is written in an explorer link's fragment (`#key=value&…`): bytes
//! outside the unreserved set and the grammar's own separators percent-encoded. The
//! explorer reads links (`app::link`); the survey writes them for glyphs it found worst.

/// Bytes kept as they are in a fragment value: the unreserved ones and the separators
/// the grammar itself uses inside values (`,` `:` `@` `+`).
fn kept(b: u8) -> bool {
    b.is_ascii_alphanumeric() || b"-._~,:@+".contains(&b)
}

/// `text` as a fragment value.
pub fn encode(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for &b in text.as_bytes() {
        if kept(b) {
            out.push(char::from(b));
        } else {
            out.push_str(&format!("%{b:02X}"));
        }
    }
    out
}

/// A fragment value as text, or what is wrong with its escapes.
pub fn decode(text: &str) -> Result<String, String> {
    let bytes = text.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        if bytes[i] == b'%' {
            let hex = bytes
                .get(i + 1..i + 3)
                .and_then(|h| std::str::from_utf8(h).ok())
                .and_then(|h| u8::from_str_radix(h, 16).ok())
                .ok_or_else(|| {
                    // By characters: the bytes after a '%' may be a character's middle.
                    let escape: String = text[i..].chars().take(3).collect();
                    format!("'{escape}' is not a %XX escape")
                })?;
            out.push(hex);
            i += 3;
        } else {
            out.push(bytes[i]);
            i += 1;
        }
    }
    String::from_utf8(out).map_err(|_| "not UTF-8 once unescaped".into())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_round_trip_and_separators_stay_readable() {
        for text in ["a b&c=d#e%f", "ক্ষ\nx", "/fonts/My Font.ttf", "1.5,-2"] {
            assert_eq!(decode(&encode(text)).unwrap(), text);
        }
        assert_eq!(encode("1.5,-2:x@y+z"), "1.5,-2:x@y+z");
        assert_eq!(encode("#36 /"), "%2336%20%2F");
        assert!(decode("%zz").unwrap_err().contains("%zz"));
    }
}
