package io.concord.jadecompat.beans;

/** Not an ontology class: BeanOntology.add(packageName) leaves it out. */
public class NotContent {
}
