package io.concord.jadecompat.beans;

import jade.content.Concept;

/** A concept found by BeanOntology.add(packageName). */
public class Planet implements Concept {
    private String name;

    public String getName() {
        return name;
    }

    public void setName(String name) {
        this.name = name;
    }
}
