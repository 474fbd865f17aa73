//! The pest grammar `grammar/chasles.pest` compiled into a parser:
//! [`ChaslesParser`] and its [`Rule`]s. The grammar file is the syntax
//! reference (LANGUAGE.md §§2, 4); `parser` builds trees from its pairs and
//! `rules` names its rules in error messages.

use pest_derive::Parser;

/// The pest parser of one statement (`Rule::statement`).
#[derive(Parser)]
#[grammar = "grammar/chasles.pest"]
pub(crate) struct ChaslesParser;
