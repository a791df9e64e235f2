import jade.content.*;


/** A bean of the music shop's ontology. */
public class Owns implements Predicate {
    private Person owner;
    private Concept thing;

    public Person getOwner() {
        return owner;
    }

    public void setOwner(Person owner) {
        this.owner = owner;
    }

    public Concept getThing() {
        return thing;
    }

    public void setThing(Concept thing) {
        this.thing = thing;
    }
}
