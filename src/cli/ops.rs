//! The set-valued subcommands (the Boolean operations and `convert`), one generic path for all.

use super::args::{ReadOpts, WriteOpts};
use super::encode::encode;
use super::error::CliError;
use super::format::Format;
use super::input::{load, one_stdin};
use super::output::write_text;
use super::progress;
use crate::num::Num;
use crate::yin2::YinSet2;
use std::path::Path;

/// A set-valued operation on one or more sets.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Op {
    /// A ∧ B.
    Meet,
    /// A ∨ B.
    Join,
    /// A′.
    Complement,
    /// A ∧ B′.
    Difference,
    /// (A ∧ B′) ∨ (A′ ∧ B).
    Xor,
    /// A itself (a change of format).
    Convert,
}

impl Op {
    /// The result on `first` and the `rest` (binary operations fold left over the rest).
    pub fn apply<N: Num>(self, first: &YinSet2<N>, rest: &[YinSet2<N>]) -> YinSet2<N> {
        let step: fn(&YinSet2<N>, &YinSet2<N>) -> YinSet2<N> = match self {
            Op::Meet => YinSet2::meet,
            Op::Join => YinSet2::join,
            Op::Difference => YinSet2::difference,
            Op::Xor => YinSet2::symmetric_difference,
            Op::Complement => return first.complement(),
            Op::Convert => return first.clone(),
        };
        rest.iter().fold(first.clone(), |acc, s| step(&acc, s))
    }
}

/// Read `inputs`, apply `op`, write the result as `write` says.
pub fn operate<N: Num>(
    op: Op,
    inputs: &[&Path],
    read: &ReadOpts,
    write: &WriteOpts,
    ctx: N::Ctx,
) -> Result<(), CliError> {
    one_stdin(inputs.iter().copied())?;
    let format = Format::of_output(write.output.as_deref(), write.to)?;
    let sets = inputs
        .iter()
        .map(|p| load::<N>(p, read, ctx))
        .collect::<Result<Vec<_>, _>>()?;
    let Some((first, rest)) = sets.split_first() else {
        return Err(CliError::Usage("no input set given".to_string()));
    };
    let vertices = sets.iter().flat_map(|s| s.curves()).map(|c| c.len()).sum();
    let message = || {
        format!(
            "{} of {vertices} vertices",
            format!("{op:?}").to_lowercase()
        )
    };
    let result = progress::while_working(message, vertices, || op.apply(first, rest));
    write_text(write.output.as_deref(), &encode(&result, format)?)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::Point;
    use crate::num::Rational;

    fn square(x: i64, y: i64, s: i64) -> YinSet2<Rational> {
        let p = |a, b| Point::int(a, b);
        YinSet2::from_curves(vec![vec![
            p(x, y),
            p(x + s, y),
            p(x + s, y + s),
            p(x, y + s),
        ]])
        .unwrap()
    }

    #[test]
    fn each_op_is_the_kernel_operation() {
        let (a, b) = (square(0, 0, 2), square(1, 1, 2));
        let two = [b.clone()];
        assert_eq!(Op::Meet.apply(&a, &two), &a & &b);
        assert_eq!(Op::Join.apply(&a, &two), &a | &b);
        assert_eq!(Op::Difference.apply(&a, &two), &a - &b);
        assert_eq!(Op::Xor.apply(&a, &two), &a ^ &b);
        assert_eq!(Op::Complement.apply(&a, &[]), !&a);
        assert_eq!(Op::Convert.apply(&a, &[]), a);
    }
}
