import jade.content.Concept;

/** A part, a plain bean. */
public class Part implements Concept {
    private String label;

    public Part() {
    }

    public Part(String label) {
        this.label = label;
    }

    public String getLabel() {
        return label;
    }

    public void setLabel(String label) {
        this.label = label;
    }
}
