//! Exit statuses, ordered by severity.

/// How a command ended. A run over several files ends with the most severe status.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Status {
    /// Success (exit 0).
    Ok,
    /// A replay did not reproduce (exit 1).
    Desync,
    /// A bad argument, an unreadable or invalid input, or a failed write (exit 2).
    Invalid,
}

impl Status {
    /// The process exit code.
    pub const fn code(self) -> i32 {
        match self {
            Status::Ok => 0,
            Status::Desync => 1,
            Status::Invalid => 2,
        }
    }
}
