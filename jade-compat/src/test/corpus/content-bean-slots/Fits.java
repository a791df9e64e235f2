import jade.content.Predicate;

/** A predicate: a gadget fits a part. */
public class Fits implements Predicate {
    private Gadget gadget;
    private Part part;

    public Gadget getGadget() {
        return gadget;
    }

    public void setGadget(Gadget gadget) {
        this.gadget = gadget;
    }

    public Part getPart() {
        return part;
    }

    public void setPart(Part part) {
        this.part = part;
    }
}
