package io.concord.core.content;

/**
 * A piece of content in its abstract form, independent of the language that writes it and of
 * the Java classes an ontology maps it to: a primitive, a variable, an aggregate or a compound
 * (concept, predicate, action, logical formula, referential expression).
 */
public sealed interface AbsObject permits AbsPrimitive, AbsVariable, AbsAggregate, AbsCompound {
}
