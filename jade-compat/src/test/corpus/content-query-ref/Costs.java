import jade.content.*;


/** A bean of the music shop's ontology. */
public class Costs implements Predicate {
    private Item item;
    private float price;

    public Item getItem() {
        return item;
    }

    public void setItem(Item item) {
        this.item = item;
    }

    public float getPrice() {
        return price;
    }

    public void setPrice(float price) {
        this.price = price;
    }
}
