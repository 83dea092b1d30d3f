//! gen-rapid
