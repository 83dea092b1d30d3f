//! Reads a crate's source files as the tidy rules need them: the module tree (`mod` items, with
//! `#[path]` and `#[cfg(test)]`), and per file the modules its code names (`use` trees, paths in
//! code and types, `crate::` / `super::` paths inside macro calls), parsed with `syn`. Test code
//! (an item under `#[cfg(test)]`, a file declared under it) is left out: tests may use any
//! module to build their fixtures.

use proc_macro2::{TokenStream, TokenTree};
use std::collections::{BTreeMap, BTreeSet};
use syn::visit::Visit;

/// A source file: its path relative to the source directory (`plan/wave/mod.rs`) and its text.
pub struct Source {
    pub path: String,
    pub text: String,
}

impl Source {
    pub fn new(path: &str, text: &str) -> Source {
        Source {
            path: path.to_string(),
            text: text.to_string(),
        }
    }
}

/// A module path from the crate root (`["plan", "wave"]`); the root is empty.
pub type ModPath = Vec<String>;

/// The crate as the rules see it.
#[derive(Debug, Default)]
pub struct Crate {
    /// Every module, inline ones included, and the file that holds it.
    pub modules: BTreeMap<ModPath, String>,
    /// The files of test code only (declared under `#[cfg(test)]`, or below such a module).
    pub test_files: BTreeSet<String>,
    /// Per file outside test code: each module its code names, with the path as written.
    pub uses: BTreeMap<String, Vec<Use>>,
}

/// A module a file's code names.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub struct Use {
    /// The module named (the deepest module of the path), and the module the path is written in.
    pub target: ModPath,
    pub from: ModPath,
    /// The path as written (`crate::plan::cspace::Node`).
    pub written: String,
}

/// A path written in a module, not yet resolved.
struct Raw {
    file: String,
    scope: ModPath,
    segments: Vec<String>,
}

/// Parses the crate whose root file is `root` (`lib.rs`) among `sources`.
pub fn parse(sources: &[Source], root: &str) -> Result<Crate, String> {
    let texts: BTreeMap<&str, &str> = sources
        .iter()
        .map(|s| (s.path.as_str(), s.text.as_str()))
        .collect();
    let mut krate = Crate::default();
    let mut raws = Vec::new();
    let mut queue = vec![(root.to_string(), ModPath::new(), false)];
    while let Some((file, module, test)) = queue.pop() {
        let text = texts
            .get(file.as_str())
            .ok_or_else(|| format!("{file}: declared by a `mod` item but not found"))?;
        let parsed = syn::parse_file(text).map_err(|e| format!("{file}: {e}"))?;
        krate.modules.insert(module.clone(), file.clone());
        if test {
            krate.test_files.insert(file.clone());
        } else {
            krate.uses.entry(file.clone()).or_default();
        }
        let walk = Walk {
            file: &file,
            dir: child_dir(&file, root),
            texts: &texts,
        };
        walk.items(
            &parsed.items,
            &module,
            &[],
            test,
            &mut krate,
            &mut raws,
            &mut queue,
        )?;
    }
    resolve(&mut krate, raws);
    Ok(krate)
}

/// The directory a file's `mod name;` items look in: beside a `mod.rs` or the root, else in
/// the directory named like the file.
fn child_dir(file: &str, root: &str) -> String {
    let (dir, name) = file.rsplit_once('/').unwrap_or(("", file));
    let stem = name.trim_end_matches(".rs");
    if name == "mod.rs" || file == root {
        dir.to_string()
    } else {
        join(dir, stem)
    }
}

fn join(dir: &str, name: &str) -> String {
    if dir.is_empty() {
        name.to_string()
    } else {
        format!("{dir}/{name}")
    }
}

struct Walk<'a> {
    file: &'a str,
    dir: String,
    texts: &'a BTreeMap<&'a str, &'a str>,
}

impl Walk<'_> {
    /// The items of module `module`, inline in this file under the inline modules `inline`.
    #[allow(clippy::too_many_arguments)]
    fn items(
        &self,
        items: &[syn::Item],
        module: &ModPath,
        inline: &[String],
        test: bool,
        krate: &mut Crate,
        raws: &mut Vec<Raw>,
        queue: &mut Vec<(String, ModPath, bool)>,
    ) -> Result<(), String> {
        for item in items {
            let test = test || is_test(item_attrs(item));
            if let syn::Item::Mod(m) = item {
                let mut child = module.clone();
                child.push(m.ident.to_string());
                if let Some((_, content)) = &m.content {
                    krate.modules.insert(child.clone(), self.file.to_string());
                    let mut inner = inline.to_vec();
                    inner.push(m.ident.to_string());
                    self.items(content, &child, &inner, test, krate, raws, queue)?;
                } else {
                    queue.push((self.child_file(m, inline)?, child, test));
                }
                continue;
            }
            if test {
                continue;
            }
            let mut collect = Collect {
                file: self.file,
                scope: module,
                raws: &mut *raws,
            };
            collect.visit_item(item);
        }
        Ok(())
    }

    /// The file of `mod name;`: its `#[path]` (beside this file), else `name.rs` or
    /// `name/mod.rs` in this file's module directory.
    fn child_file(&self, m: &syn::ItemMod, inline: &[String]) -> Result<String, String> {
        let name = m.ident.to_string();
        for attr in &m.attrs {
            if let syn::Meta::NameValue(nv) = &attr.meta {
                if nv.path.is_ident("path") {
                    if let syn::Expr::Lit(syn::ExprLit {
                        lit: syn::Lit::Str(s),
                        ..
                    }) = &nv.value
                    {
                        let here = self.file.rsplit_once('/').map_or("", |(d, _)| d);
                        return Ok(join(here, &s.value()));
                    }
                }
            }
        }
        let dir = inline.iter().fold(self.dir.clone(), |d, m| join(&d, m));
        let flat = join(&dir, &format!("{name}.rs"));
        let nested = join(&dir, &format!("{name}/mod.rs"));
        if self.texts.contains_key(flat.as_str()) {
            Ok(flat)
        } else if self.texts.contains_key(nested.as_str()) {
            Ok(nested)
        } else {
            Err(format!(
                "{}: `mod {name};` has no file {flat} or {nested}",
                self.file
            ))
        }
    }
}

fn item_attrs(item: &syn::Item) -> &[syn::Attribute] {
    use syn::Item::*;
    match item {
        Const(i) => &i.attrs,
        Enum(i) => &i.attrs,
        ExternCrate(i) => &i.attrs,
        Fn(i) => &i.attrs,
        ForeignMod(i) => &i.attrs,
        Impl(i) => &i.attrs,
        Macro(i) => &i.attrs,
        Mod(i) => &i.attrs,
        Static(i) => &i.attrs,
        Struct(i) => &i.attrs,
        Trait(i) => &i.attrs,
        TraitAlias(i) => &i.attrs,
        Type(i) => &i.attrs,
        Union(i) => &i.attrs,
        Use(i) => &i.attrs,
        _ => &[],
    }
}

/// Whether the attributes hold `#[cfg(test)]`.
fn is_test(attrs: &[syn::Attribute]) -> bool {
    attrs.iter().any(|a| {
        a.path().is_ident("cfg") && a.parse_args::<syn::Ident>().is_ok_and(|i| i == "test")
    })
}

/// Gathers the paths an item's code writes.
struct Collect<'a> {
    file: &'a str,
    scope: &'a ModPath,
    raws: &'a mut Vec<Raw>,
}

impl Collect<'_> {
    fn push(&mut self, segments: Vec<String>) {
        if segments.len() > 1 {
            self.raws.push(Raw {
                file: self.file.to_string(),
                scope: self.scope.clone(),
                segments,
            });
        }
    }
}

impl<'ast> Visit<'ast> for Collect<'_> {
    fn visit_item(&mut self, item: &'ast syn::Item) {
        if !is_test(item_attrs(item)) {
            syn::visit::visit_item(self, item);
        }
    }

    fn visit_impl_item(&mut self, item: &'ast syn::ImplItem) {
        let attrs = match item {
            syn::ImplItem::Const(i) => &i.attrs,
            syn::ImplItem::Fn(i) => &i.attrs,
            syn::ImplItem::Type(i) => &i.attrs,
            syn::ImplItem::Macro(i) => &i.attrs,
            _ => return syn::visit::visit_impl_item(self, item),
        };
        if !is_test(attrs) {
            syn::visit::visit_impl_item(self, item);
        }
    }

    fn visit_item_use(&mut self, item: &'ast syn::ItemUse) {
        let mut flat = Vec::new();
        flatten(&item.tree, &mut Vec::new(), &mut flat);
        for segments in flat {
            self.push(segments);
        }
    }

    fn visit_path(&mut self, path: &'ast syn::Path) {
        self.push(path.segments.iter().map(|s| s.ident.to_string()).collect());
        syn::visit::visit_path(self, path);
    }

    fn visit_macro(&mut self, mac: &'ast syn::Macro) {
        self.visit_path(&mac.path);
        let mut found = Vec::new();
        macro_paths(mac.tokens.clone(), &mut found);
        for segments in found {
            self.push(segments);
        }
    }
}

/// The paths of a `use` tree, each from the tree's first segment (`self` in a group stands
/// for the group's prefix; a glob for the prefix itself).
fn flatten(tree: &syn::UseTree, prefix: &mut Vec<String>, out: &mut Vec<Vec<String>>) {
    match tree {
        syn::UseTree::Path(p) => {
            prefix.push(p.ident.to_string());
            flatten(&p.tree, prefix, out);
            prefix.pop();
        }
        syn::UseTree::Name(n) if n.ident == "self" => out.push(prefix.clone()),
        syn::UseTree::Name(n) => out.push([prefix.clone(), vec![n.ident.to_string()]].concat()),
        syn::UseTree::Rename(r) => out.push([prefix.clone(), vec![r.ident.to_string()]].concat()),
        syn::UseTree::Glob(_) => out.push(prefix.clone()),
        syn::UseTree::Group(g) => {
            for t in &g.items {
                flatten(t, prefix, out);
            }
        }
    }
}

/// The `crate::` and `super::` paths in a macro call's tokens (`ident :: ident ...`).
fn macro_paths(tokens: TokenStream, out: &mut Vec<Vec<String>>) {
    let trees: Vec<TokenTree> = tokens.into_iter().collect();
    let mut i = 0;
    while i < trees.len() {
        match &trees[i] {
            TokenTree::Group(g) => macro_paths(g.stream(), out),
            TokenTree::Ident(id) if id == "crate" || id == "super" => {
                let mut path = vec![id.to_string()];
                let mut j = i + 1;
                while let (
                    Some(TokenTree::Punct(a)),
                    Some(TokenTree::Punct(b)),
                    Some(TokenTree::Ident(n)),
                ) = (trees.get(j), trees.get(j + 1), trees.get(j + 2))
                {
                    if a.as_char() != ':' || b.as_char() != ':' {
                        break;
                    }
                    path.push(n.to_string());
                    j += 3;
                }
                out.push(path);
                i = j;
                continue;
            }
            _ => {}
        }
        i += 1;
    }
}

/// Resolves the paths gathered: `crate`, `self`, `super` and the names of child modules and of
/// modules brought in by `use` start a path inside the crate; anything else is another crate.
fn resolve(krate: &mut Crate, raws: Vec<Raw>) {
    // The module names a scope's `use` items bring in (`use crate::plan::wave::{self, ..}`).
    let mut aliases: BTreeMap<ModPath, BTreeMap<String, ModPath>> = BTreeMap::new();
    for _ in 0..2 {
        for raw in &raws {
            if let Some(target) = target_of(krate, &aliases, raw) {
                let last = raw.segments.last().cloned().unwrap_or_default();
                if target.last() == Some(&last) {
                    aliases
                        .entry(raw.scope.clone())
                        .or_default()
                        .insert(last, target);
                }
            }
        }
    }
    for raw in &raws {
        if let Some(target) = target_of(krate, &aliases, raw) {
            let uses = krate.uses.entry(raw.file.clone()).or_default();
            let u = Use {
                target,
                from: raw.scope.clone(),
                written: raw.segments.join("::"),
            };
            if !uses.contains(&u) {
                uses.push(u);
            }
        }
    }
}

/// The deepest module `raw` names, `None` for a path of another crate (or a local name).
fn target_of(
    krate: &Crate,
    aliases: &BTreeMap<ModPath, BTreeMap<String, ModPath>>,
    raw: &Raw,
) -> Option<ModPath> {
    let segs = &raw.segments;
    let mut rest = 1;
    let mut cur = match segs[0].as_str() {
        "crate" => ModPath::new(),
        "self" => raw.scope.clone(),
        "super" => {
            let mut m = raw.scope.clone();
            m.pop()?;
            while segs.get(rest).map(String::as_str) == Some("super") {
                m.pop()?;
                rest += 1;
            }
            m
        }
        name => {
            let child = [raw.scope.clone(), vec![name.to_string()]].concat();
            if krate.modules.contains_key(&child) {
                child
            } else {
                aliases.get(&raw.scope)?.get(name)?.clone()
            }
        }
    };
    for seg in &segs[rest..] {
        let next = [cur.clone(), vec![seg.clone()]].concat();
        if !krate.modules.contains_key(&next) {
            break;
        }
        cur = next;
    }
    Some(cur)
}
