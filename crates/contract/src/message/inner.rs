//! A sentence inside another: what failed beneath a reading, a check or a surface operation
//! (the grammar's error under a number's text, the engine's error under a computed erratum).
//!
//! The subjects' enums hold it by the [`Sentence`] it is worded by, not as a
//! [`crate::Message`], so that they need not name the message that names them: the message
//! module imports its subjects, and no subject imports it back.

use crate::limit::Limit;
use cagd_words::{Lang, Phrase};
use std::any::Any;
use std::fmt;
use std::sync::Arc;

/// A sentence that can be held inside another: worded in each language, with the limit of
/// the run it is a refusal by, and comparable with another sentence of its type.
pub trait Sentence: cagd_words::Message + fmt::Debug + Send + Sync + Any {
    /// The limit of the run this sentence is a refusal by, if any.
    fn limit(&self) -> Option<Limit>;
    /// Whether `other` is this same sentence.
    fn same(&self, other: &dyn Sentence) -> bool;
    /// The sentence, for [`Inner::get`].
    fn as_any(&self) -> &dyn Any;
}

/// A sentence inside another (worded in turn, in the same language).
#[derive(Clone)]
pub struct Inner(Arc<dyn Sentence>);

impl Inner {
    /// Holds the sentence `s`.
    pub(crate) fn hold(s: impl Sentence) -> Inner {
        Inner(Arc::new(s))
    }

    /// Its words in `lang`.
    pub fn phrase(&self, lang: Lang) -> Phrase {
        self.0.phrase(lang)
    }

    /// The limit of the run the inner sentence is a refusal by, if any.
    pub fn limit(&self) -> Option<Limit> {
        self.0.limit()
    }

    /// The inner sentence, if it is a `T`.
    pub fn get<T: Sentence>(&self) -> Option<&T> {
        self.0.as_any().downcast_ref()
    }
}

impl fmt::Debug for Inner {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Debug::fmt(&*self.0, f)
    }
}

impl PartialEq for Inner {
    fn eq(&self, other: &Inner) -> bool {
        self.0.same(&*other.0)
    }
}

impl Eq for Inner {}
