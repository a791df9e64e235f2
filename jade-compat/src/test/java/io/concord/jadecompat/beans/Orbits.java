package io.concord.jadecompat.beans;

import jade.content.Predicate;

/** A predicate found by BeanOntology.add(packageName). */
public class Orbits implements Predicate {
    private Planet planet;

    public Planet getPlanet() {
        return planet;
    }

    public void setPlanet(Planet planet) {
        this.planet = planet;
    }
}
