//! The one error type of the core. Every failure a user can cause is a value here with a
//! message that names the field and what is allowed; nothing in the core panics on bad input.

use serde::Serialize;
use std::fmt;

/// Why a generation was refused. Serialises as `{"kind": "...", "param": "...", "message": "..."}`,
/// the shape the web worker and the CLI pass on unchanged.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum SylvaError {
    /// A parameter value is outside its range, not finite, or not a whole number where one is needed.
    InvalidParam {
        /// The parameter id, e.g. `l1_length`.
        param: String,
        /// Human-readable message naming the parameter and its allowed range.
        message: String,
    },
    /// A parameter id that the registry does not know.
    UnknownParam {
        /// The id as given.
        param: String,
        /// Human-readable message.
        message: String,
    },
    /// The tree would exceed a budget (vertices, stems, leaves, ...).
    Budget {
        /// The budget parameter that was hit, e.g. `max_vertices`.
        param: String,
        /// Human-readable message with the numbers.
        message: String,
    },
    /// Malformed input that is not about one parameter (e.g. JSON that is not an object).
    Input {
        /// Human-readable message.
        message: String,
    },
}

impl SylvaError {
    /// The message shown to users.
    pub fn message(&self) -> &str {
        match self {
            SylvaError::InvalidParam { message, .. }
            | SylvaError::UnknownParam { message, .. }
            | SylvaError::Budget { message, .. }
            | SylvaError::Input { message } => message,
        }
    }

    /// The error as the JSON object the worker protocol and the CLI print.
    pub fn to_json(&self) -> String {
        serde_json::to_string(self).unwrap_or_else(|_| "{\"kind\":\"input\",\"message\":\"error\"}".into())
    }
}

impl fmt::Display for SylvaError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.message())
    }
}

impl std::error::Error for SylvaError {}
