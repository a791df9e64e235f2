import java.io.Serializable;

/** A Java object sent as message content. */
public class Order implements Serializable {
    private static final long serialVersionUID = 1L;
    final String item;
    final int quantity;

    public Order(String item, int quantity) {
        this.item = item;
        this.quantity = quantity;
    }

    @Override
    public String toString() {
        return quantity + " x " + item;
    }
}
