//! The typed syntax tree of a PDDL domain and problem in the supported fragment.
//!
//! All names are lowercase (PDDL is case-insensitive). Every node that can be the subject
//! of a diagnostic carries a [`Span`]; spans never take part in equality.

use crate::Span;

/// A name as written: a type, predicate, function, action, object or variable (with its
/// leading `?`).
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct Name {
    /// The lowercase text.
    pub text: String,
    /// Where it was written.
    pub span: Span,
}

impl Name {
    /// A name that was not parsed from text.
    pub fn new(text: impl Into<String>) -> Name {
        Name {
            text: text.into(),
            span: Span::NONE,
        }
    }

    /// The text.
    pub fn as_str(&self) -> &str {
        &self.text
    }
}

/// The type of a typed item: a named type or `(either t1 t2 ...)`.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum Type {
    /// A single type.
    Named(Name),
    /// A union of types.
    Either(Vec<Name>),
}

impl Type {
    /// The named types this type is made of.
    pub fn names(&self) -> &[Name] {
        match self {
            Type::Named(n) => std::slice::from_ref(n),
            Type::Either(ns) => ns,
        }
    }
}

/// A name with an optional type, as in `?x - block` or `a b - truck`. `None` means no
/// type was written (the type is `object`).
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct Typed {
    /// The variable, object or type name.
    pub name: Name,
    /// The declared type or parent type.
    pub ty: Option<Type>,
}

/// An argument of an atom: a parameter (`?x`) or an object or constant.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum Term {
    /// A variable, with its `?`.
    Variable(Name),
    /// A constant of the domain or an object of the problem.
    Object(Name),
}

impl Term {
    /// The name of the variable or object.
    pub fn name(&self) -> &Name {
        match self {
            Term::Variable(n) | Term::Object(n) => n,
        }
    }
}

/// A predicate applied to terms. Equality is the predicate `=`.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct Atom {
    /// The predicate name, or `=`.
    pub predicate: Name,
    /// The arguments.
    pub args: Vec<Term>,
    /// The whole atom, parentheses included.
    pub span: Span,
}

impl Atom {
    /// True for `(= a b)`.
    pub fn is_equality(&self) -> bool {
        self.predicate.text == "="
    }
}

/// An atom or its negation. Preconditions and goals are conjunctions of literals.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct Literal {
    /// False for `(not atom)`.
    pub positive: bool,
    /// The atom.
    pub atom: Atom,
}

/// A function applied to terms, as in `(road-length ?from ?to)` or `(total-cost)`.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct FunctionTerm {
    /// The function name.
    pub function: Name,
    /// The arguments.
    pub args: Vec<Term>,
    /// The whole term, parentheses included.
    pub span: Span,
}

/// An integer written in the text.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Number {
    /// The value; action costs use 64 bits (parcprinter's reach millions).
    pub value: i64,
    /// Where it was written.
    pub span: Span,
}

/// What an action adds to `total-cost`.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum CostExpr {
    /// A constant.
    Constant(Number),
    /// A static function whose values the problem's `:init` sets.
    Function(FunctionTerm),
}

/// One effect of an action.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum Effect {
    /// The atom becomes true.
    Add(Atom),
    /// `(not atom)`: the atom becomes false.
    Delete(Atom),
    /// `(increase (total-cost) expr)`.
    IncreaseCost(CostExpr),
}

/// A predicate declaration, `(on ?x ?y - block)`.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct PredicateDecl {
    /// The name.
    pub name: Name,
    /// The typed parameters. Names may repeat (logistics00 declares `(in ?obj ?obj)`);
    /// only the count matters.
    pub params: Vec<Typed>,
}

/// A numeric function declaration. In the fragment only `total-cost` and static cost
/// functions such as `(road-length ?a ?b - location)` exist, all of type `number`.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct FunctionDecl {
    /// The name.
    pub name: Name,
    /// The typed parameters.
    pub params: Vec<Typed>,
}

/// An action schema.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct Action {
    /// The name.
    pub name: Name,
    /// The typed parameters.
    pub params: Vec<Typed>,
    /// The precondition, a conjunction (nested `and`s are flattened).
    pub precondition: Vec<Literal>,
    /// The effects, in order.
    pub effects: Vec<Effect>,
}

/// A requirement flag as declared, e.g. `:typing`. Kept as written: demoplan judges a
/// file by the constructs it uses, not by what it declares (as Fast Downward does).
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct Requirement {
    /// The flag with its colon, lowercase.
    pub name: String,
    /// Where it was written.
    pub span: Span,
}

/// A PDDL domain.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct Domain {
    /// The domain name.
    pub name: Name,
    /// Declared requirements.
    pub requirements: Vec<Requirement>,
    /// Type declarations in order; a type may be declared more than once, with different
    /// parents (storage does). `object` is the implicit root.
    pub types: Vec<Typed>,
    /// Constants.
    pub constants: Vec<Typed>,
    /// Predicates.
    pub predicates: Vec<PredicateDecl>,
    /// Functions.
    pub functions: Vec<FunctionDecl>,
    /// Action schemas.
    pub actions: Vec<Action>,
}

/// An entry of a problem's `:init`.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum InitEntry {
    /// A ground fact.
    Fact(Atom),
    /// `(= (f a b) 5)`: the value of a function.
    FunctionValue {
        /// The ground function term.
        term: FunctionTerm,
        /// Its value.
        value: Number,
    },
}

/// The problem's metric. The fragment knows one: minimise `total-cost`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Metric {
    /// Where it was written.
    pub span: Span,
}

/// A PDDL problem.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct Problem {
    /// The problem name.
    pub name: Name,
    /// The domain it names in `(:domain ...)`.
    pub domain: Name,
    /// Declared requirements.
    pub requirements: Vec<Requirement>,
    /// Objects.
    pub objects: Vec<Typed>,
    /// Initial facts and function values.
    pub init: Vec<InitEntry>,
    /// The goal, a conjunction of ground literals.
    pub goal: Vec<Literal>,
    /// `(:metric minimize (total-cost))`, if given.
    pub metric: Option<Metric>,
}
