//! Text from and for the user: reading the user's files (method files here, scene files
//! in the application) under a size bound, saying on one line where in a file a problem
//! is, and printing numbers with the digits that matter.

mod input;
mod location;
mod number;

pub use input::{limit, read_text, read_text_within, DEFAULT_LIMIT_MIB, LIMIT_VARIABLE};
pub use location::{line_column, one_line, toml_message};
pub use number::{number, Number};
