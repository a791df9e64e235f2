import jade.content.Concept;

/** A bean with an enum slot and array slots (double[], String[], an array of concepts). */
public class Parcel implements Concept {
    private String label;
    private Size size;
    private double[] weights;
    private String[] stickers;
    private Parcel[] inside;

    public String getLabel() {
        return label;
    }

    public void setLabel(String label) {
        this.label = label;
    }

    public Size getSize() {
        return size;
    }

    public void setSize(Size size) {
        this.size = size;
    }

    public double[] getWeights() {
        return weights;
    }

    public void setWeights(double[] weights) {
        this.weights = weights;
    }

    public String[] getStickers() {
        return stickers;
    }

    public void setStickers(String[] stickers) {
        this.stickers = stickers;
    }

    public Parcel[] getInside() {
        return inside;
    }

    public void setInside(Parcel[] inside) {
        this.inside = inside;
    }
}
