//! A method's parameters as one type. Each parameter is a row ([`ParamSpec`]) saying
//! what it accepts and what it defaults to; the text given (`--param KEY=VALUE`, a
//! pane's settings, a bench row) is checked against the rows once, by
//! [`Params::parse`], and the method reads typed values ([`Value`]) from the result —
//! it never parses text. Written back as text by [`assignments`] and [`settings_text`].

use std::fmt;

use crate::Error;

/// One parameter a method takes: what it accepts, its default, and what it does (for
/// the checks, the controls and the help alike).
#[derive(Clone, Copy, Debug)]
pub struct ParamSpec {
    pub key: &'static str,
    /// The values offered (the app's menus, the Pareto sweep); the first is the default.
    pub choices: &'static [&'static str],
    /// The numbers accepted besides the choices, if any. Without, only the choices are;
    /// with, a choice that is a number is one example of them.
    pub numbers: Option<Numbers>,
    /// What it does and what it costs.
    pub help: &'static str,
}

/// `between`, the one row two methods share (`winding` and `sdf-cells`, which draw
/// instance by instance from outlines): how instances whose ink overlaps are drawn.
pub const BETWEEN: ParamSpec = ParamSpec {
    key: "between",
    choices: &["union", "add"],
    numbers: None,
    help: "union (the default under the nonzero rule): instances whose ink overlaps \
           (joined letters, vowel signs over their bases, box-drawing characters meeting, \
           a kerned pair) are drawn as one glyph whose fill is their union \
           (Scene::with_overlapping_instances_joined), so shared ink counts once, as in \
           the reference; add: each instance alone, their coverages added, so shared ink \
           counts twice (what per-glyph compositing gives).",
};

/// The numbers a parameter accepts besides its choices.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Numbers {
    /// Whole numbers from `min` to `max` (a band count, a number of passes).
    Whole { min: u32, max: u32 },
    /// Finite numbers from `min` to `max` (`f64::INFINITY`: no upper bound), in `unit`
    /// ("" for none), as error messages name them.
    Real {
        min: f64,
        max: f64,
        unit: &'static str,
    },
}

/// A parameter's value, checked against its row.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Value {
    /// One of the row's choices, taken as it is written: every choice of a row without
    /// numbers (`exact`, `off`, or `4` of a fixed set), the others (`auto`) of a row
    /// with them.
    Word(&'static str),
    Whole(u32),
    Real(f64),
}

impl Value {
    pub fn word(self) -> Option<&'static str> {
        match self {
            Value::Word(word) => Some(word),
            _ => None,
        }
    }

    pub fn whole(self) -> Option<u32> {
        match self {
            Value::Whole(n) => Some(n),
            _ => None,
        }
    }

    pub fn real(self) -> Option<f64> {
        match self {
            Value::Real(x) => Some(x),
            _ => None,
        }
    }
}

/// As `--param` takes it back: the word, or the number in Rust's shortest form that
/// reads back as the same number.
impl fmt::Display for Value {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Value::Word(word) => f.write_str(word),
            Value::Whole(n) => write!(f, "{n}"),
            Value::Real(x) => write!(f, "{x}"),
        }
    }
}

impl ParamSpec {
    /// `text` as this row reads it, if the row accepts it.
    pub fn value(&self, text: &str) -> Option<Value> {
        match self.numbers {
            Some(Numbers::Whole { min, max }) => {
                if let Ok(n) = text.parse::<u32>() {
                    return (min..=max).contains(&n).then_some(Value::Whole(n));
                }
            }
            Some(Numbers::Real { min, max, .. }) => {
                if let Ok(x) = text.parse::<f64>() {
                    let within = x.is_finite() && min <= x && x <= max;
                    return within.then_some(Value::Real(x));
                }
            }
            None => {}
        }
        self.choices
            .iter()
            .find(|&&choice| choice == text)
            .map(|&choice| Value::Word(choice))
    }

    /// The value taken when the parameter is not given: the first choice.
    pub fn default_value(&self) -> Option<Value> {
        self.choices.first().and_then(|choice| self.value(choice))
    }

    /// What the row accepts, in words: `1 or 4`, `auto, off or a whole number from 1
    /// to 64`, `a number of em from 0 to 0.5`.
    pub fn allowed(&self) -> String {
        type Parsed<'a> = Vec<(f64, &'a str)>;
        let (mut numbers, words): (Parsed, Parsed) = self
            .choices
            .iter()
            .map(|c| (c.parse::<f64>().unwrap_or(f64::NAN), *c))
            .partition(|(x, _)| !x.is_nan());
        let items: Vec<String> = match self.numbers {
            // A fixed set: its numbers ascending, then its words.
            None => {
                numbers.sort_by(|a, b| a.0.total_cmp(&b.0));
                numbers
                    .iter()
                    .chain(&words)
                    .map(|(_, c)| c.to_string())
                    .collect()
            }
            // The words, then the range: the choices that are numbers are examples of it.
            Some(range) => words
                .iter()
                .map(|(_, c)| c.to_string())
                .chain([range.to_string()])
                .collect(),
        };
        match items.split_last() {
            Some((last, [])) => last.clone(),
            Some((last, rest)) => format!("{} or {last}", rest.join(", ")),
            None => "nothing".to_owned(),
        }
    }
}

/// The range in words: `a whole number from 1 to 64`, `a number of em from 0 to 0.5`,
/// `a number ≥ 0`.
impl fmt::Display for Numbers {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Numbers::Whole { min, max } => write!(f, "a whole number from {min} to {max}"),
            Numbers::Real { min, max, unit } => {
                f.write_str("a number")?;
                if !unit.is_empty() {
                    write!(f, " of {unit}")?;
                }
                if max.is_infinite() {
                    write!(f, " ≥ {min}")
                } else {
                    write!(f, " from {min} to {max}")
                }
            }
        }
    }
}

/// A method's parameters, every value given checked against the method's rows: what
/// its constructor reads.
#[derive(Clone, Debug)]
pub struct Params {
    rows: &'static [ParamSpec],
    /// The values given, one per key (the last given wins), in the order first given.
    given: Vec<(&'static str, Value)>,
}

impl Params {
    /// Checks `given` (`KEY=VALUE` pairs, as `--param` takes them) against `rows`, the
    /// parameters of `method`: an unknown key, or a value its row does not accept, is
    /// an [`Error::Input`] of one line that names the method, the key and what it takes.
    pub fn parse(
        method: &str,
        rows: &'static [ParamSpec],
        given: &[(String, String)],
    ) -> Result<Params, Error> {
        let mut params = Params {
            rows,
            given: Vec::new(),
        };
        for (key, text) in given {
            let row = rows.iter().find(|row| row.key == key).ok_or_else(|| {
                let keys: Vec<&str> = rows.iter().map(|row| row.key).collect();
                Error::Input(if keys.is_empty() {
                    format!("method '{method}' takes no parameters (got '{key}')")
                } else {
                    format!(
                        "method '{method}' has no parameter '{key}'; it takes: {}",
                        keys.join(", ")
                    )
                })
            })?;
            let value = row.value(text).ok_or_else(|| {
                Error::Input(format!(
                    "method '{method}': {key}={text} is not valid; {key} must be {}",
                    row.allowed()
                ))
            })?;
            match params.given.iter_mut().find(|(k, _)| *k == row.key) {
                Some(slot) => slot.1 = value,
                None => params.given.push((row.key, value)),
            }
        }
        Ok(params)
    }

    /// The value of `key` if it was given.
    pub fn given(&self, key: &str) -> Option<Value> {
        self.given.iter().find(|(k, _)| *k == key).map(|&(_, v)| v)
    }

    /// The value of `key`: as given, or its row's default. None for a key the method
    /// does not take.
    pub fn get(&self, key: &str) -> Option<Value> {
        self.given(key).or_else(|| {
            self.rows
                .iter()
                .find(|row| row.key == key)
                .and_then(ParamSpec::default_value)
        })
    }

    /// The value of `key` if it is a word (see [`Params::get`]).
    pub fn word(&self, key: &str) -> Option<&'static str> {
        self.get(key).and_then(Value::word)
    }

    /// The value of `key` if it is a whole number (see [`Params::get`]).
    pub fn whole(&self, key: &str) -> Option<u32> {
        self.get(key).and_then(Value::whole)
    }

    /// The value of `key` if it is a number that need not be whole (see
    /// [`Params::get`]).
    pub fn real(&self, key: &str) -> Option<f64> {
        self.get(key).and_then(Value::real)
    }
}

/// Each pair as `key=value`, in the order given: how `--param` writes one.
pub fn assignments<'a>(
    pairs: impl IntoIterator<Item = &'a (String, String)>,
) -> impl Iterator<Item = String> {
    pairs.into_iter().map(|(k, v)| format!("{k}={v}"))
}

/// Parameters as `k=v, k=v`, or `default` when there are none: how tables and reports
/// name a setting. Keys in `leaving_out` are not named (the bench leaves out what it
/// sets per scene rather than per setting).
pub fn settings_text(pairs: &[(String, String)], leaving_out: &[&str]) -> String {
    let shown: Vec<String> = assignments(
        pairs
            .iter()
            .filter(|(k, _)| !leaving_out.contains(&k.as_str())),
    )
    .collect();
    if shown.is_empty() {
        "default".into()
    } else {
        shown.join(", ")
    }
}

/// The text given for `key`, if any (the last one wins), before any check.
pub fn given_text<'a>(pairs: &'a [(String, String)], key: &str) -> Option<&'a str> {
    pairs
        .iter()
        .rev()
        .find(|(k, _)| k == key)
        .map(|(_, v)| v.as_str())
}

/// Pairs written in the code (a bench setting, a claim's setting) as the owned pairs
/// `--param` gives.
pub fn owned(pairs: &[(&str, &str)]) -> Vec<(String, String)> {
    pairs
        .iter()
        .map(|&(k, v)| (k.to_owned(), v.to_owned()))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Rows of every kind, written for these tests (not any method's).
    const ROWS: &[ParamSpec] = &[
        ParamSpec {
            key: "mode",
            choices: &["fast", "exact"],
            numbers: None,
            help: "",
        },
        ParamSpec {
            key: "msaa",
            choices: &["4", "1", "16"],
            numbers: None,
            help: "",
        },
        ParamSpec {
            key: "count",
            choices: &["auto", "8", "off"],
            numbers: Some(Numbers::Whole { min: 1, max: 64 }),
            help: "",
        },
        ParamSpec {
            key: "width",
            choices: &["0.1"],
            numbers: Some(Numbers::Real {
                min: -0.5,
                max: 0.5,
                unit: "em",
            }),
            help: "",
        },
        ParamSpec {
            key: "threshold",
            choices: &["3"],
            numbers: Some(Numbers::Real {
                min: 0.0,
                max: f64::INFINITY,
                unit: "",
            }),
            help: "",
        },
    ];

    fn parse(pairs: &[(&str, &str)]) -> Result<Params, Error> {
        Params::parse("demo", ROWS, &owned(pairs))
    }

    /// The one line `parse` refuses `pairs` with.
    fn refusal(pairs: &[(&str, &str)]) -> String {
        match parse(pairs) {
            Err(Error::Input(message)) => {
                assert!(!message.contains('\n'), "{message}");
                message
            }
            other => panic!("{pairs:?}: {other:?}"),
        }
    }

    #[test]
    fn values_are_read_as_their_row_says() {
        let params = parse(&[
            ("mode", "exact"),
            ("msaa", "16"),
            ("count", "12"),
            ("width", "-0.25"),
            ("threshold", "1e3"),
        ])
        .unwrap();
        assert_eq!(params.get("mode"), Some(Value::Word("exact")));
        // A number among the choices of a row without numbers is a word like any other.
        assert_eq!(params.get("msaa"), Some(Value::Word("16")));
        assert_eq!(params.get("count"), Some(Value::Whole(12)));
        assert_eq!(params.get("width"), Some(Value::Real(-0.25)));
        assert_eq!(params.real("threshold"), Some(1000.0));
        assert_eq!(
            parse(&[("count", "off")]).unwrap().word("count"),
            Some("off")
        );
        assert_eq!(parse(&[("count", "8")]).unwrap().whole("count"), Some(8));
    }

    #[test]
    fn a_value_not_given_is_its_rows_default_and_the_last_given_wins() {
        let params = parse(&[("count", "3"), ("mode", "exact"), ("count", "5")]).unwrap();
        assert_eq!(params.given("count"), Some(Value::Whole(5)));
        assert_eq!(params.given("msaa"), None);
        assert_eq!(params.get("msaa"), Some(Value::Word("4")));
        assert_eq!(params.get("width"), Some(Value::Real(0.1)));
        assert_eq!(params.get("colour"), None, "not a parameter of this method");
        assert_eq!(parse(&[]).unwrap().word("mode"), Some("fast"));
    }

    #[test]
    fn every_value_reads_back_from_its_text() {
        for (key, text) in [
            ("mode", "exact"),
            ("msaa", "1"),
            ("count", "64"),
            ("count", "auto"),
            ("width", "-0.5"),
            ("width", "0.0625"),
            ("threshold", "12.5"),
        ] {
            let value = parse(&[(key, text)]).unwrap().get(key).unwrap();
            assert_eq!(value.to_string(), text);
            let again = parse(&[(key, &value.to_string())]).unwrap();
            assert_eq!(again.get(key), Some(value), "{key}={text}");
        }
        // A number is written back in its shortest form.
        let wide = parse(&[("width", "0.50")]).unwrap();
        assert_eq!(wide.get("width").unwrap().to_string(), "0.5");
    }

    #[test]
    fn an_unknown_key_names_the_method_and_the_keys_it_takes() {
        assert_eq!(
            refusal(&[("colour", "red")]),
            "method 'demo' has no parameter 'colour'; it takes: mode, msaa, count, width, \
             threshold"
        );
        match Params::parse("plain", &[], &owned(&[("mode", "fast")])) {
            Err(Error::Input(message)) => {
                assert_eq!(message, "method 'plain' takes no parameters (got 'mode')")
            }
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn a_value_outside_its_row_names_the_method_the_key_and_what_is_allowed() {
        for (key, text, allowed) in [
            // Not one of the choices.
            ("mode", "slow", "fast or exact"),
            // Numbers first, ascending: a fixed set reads as one.
            ("msaa", "8", "1, 4 or 16"),
            // Out of range, and of the wrong kind.
            ("count", "0", "auto, off or a whole number from 1 to 64"),
            ("count", "65", "auto, off or a whole number from 1 to 64"),
            ("count", "2.5", "auto, off or a whole number from 1 to 64"),
            ("count", "-1", "auto, off or a whole number from 1 to 64"),
            ("width", "0.6", "a number of em from -0.5 to 0.5"),
            ("width", "wide", "a number of em from -0.5 to 0.5"),
            ("width", "nan", "a number of em from -0.5 to 0.5"),
            ("threshold", "-1", "a number ≥ 0"),
            ("threshold", "inf", "a number ≥ 0"),
            ("threshold", "1e400", "a number ≥ 0"),
        ] {
            assert_eq!(
                refusal(&[(key, text)]),
                format!("method 'demo': {key}={text} is not valid; {key} must be {allowed}")
            );
        }
        // Every value given is checked, not only the one that wins.
        assert!(parse(&[("mode", "slow"), ("mode", "fast")]).is_err());
    }

    #[test]
    fn settings_are_named_as_given_leaving_out_what_is_asked() {
        let pairs = owned(&[("aa", "rays"), ("cache", "32"), ("samples", "1")]);
        assert_eq!(settings_text(&pairs, &[]), "aa=rays, cache=32, samples=1");
        assert_eq!(settings_text(&pairs, &["cache"]), "aa=rays, samples=1");
        assert_eq!(settings_text(&pairs[1..2], &["cache"]), "default");
        assert_eq!(settings_text(&[], &[]), "default");
        assert_eq!(
            assignments(&pairs).collect::<Vec<_>>(),
            ["aa=rays", "cache=32", "samples=1"]
        );
        assert_eq!(
            given_text(&owned(&[("a", "1"), ("a", "2")]), "a"),
            Some("2")
        );
    }
}
