//! Collects every error of one expansion so that a single build shows all of them.

use proc_macro2::TokenStream;
use quote::ToTokens;
use std::fmt::Display;

#[derive(Default)]
pub struct Errors {
    errors: Vec<syn::Error>,
}

impl Errors {
    pub fn new() -> Self {
        Self::default()
    }

    pub fn error_spanned_by<T: ToTokens, M: Display>(&mut self, tokens: T, message: M) {
        self.errors.push(syn::Error::new_spanned(tokens, message));
    }

    pub fn error_at<M: Display>(&mut self, span: proc_macro2::Span, message: M) {
        self.errors.push(syn::Error::new(span, message));
    }

    /// Adds `other`'s errors after these.
    pub fn append(&mut self, other: Errors) {
        self.errors.extend(other.errors);
    }

    pub fn count(&self) -> usize {
        self.errors.len()
    }

    pub fn is_empty(&self) -> bool {
        self.errors.is_empty()
    }

    pub fn into_compile_errors(self) -> TokenStream {
        self.into_compile_errors_under(None)
    }

    /// The errors as `compile_error!`s, each under `#[cfg(condition)]` when one is given.
    pub fn into_compile_errors_under(self, condition: Option<&TokenStream>) -> TokenStream {
        self.errors
            .into_iter()
            .map(|error| {
                let tokens = error.to_compile_error();
                match condition {
                    Some(condition) => quote::quote!(#[cfg(#condition)] #tokens),
                    None => tokens,
                }
            })
            .collect()
    }
}
